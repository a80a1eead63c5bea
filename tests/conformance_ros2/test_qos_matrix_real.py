"""The committed QoS record (qos_matrix_jazzy.json, which rosgrade's rclpy is tested against in
tests/nodelib_ros2_rclpy/test_qos_matching.py) is still what real rclpy does: recorded again from two real Jazzy
nodes when the venv is there."""
from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from real_ros2 import unavailable_reason  # noqa: E402
from record_qos_matrix import ROLES, record_matrix  # noqa: E402

pytestmark = pytest.mark.slow

RECORD = Path(__file__).resolve().parent / "qos_matrix_jazzy.json"


def test_real_rclpy_matches_the_committed_qos_record() -> None:
    reason = unavailable_reason()
    if reason:
        pytest.skip(reason)
    committed = json.loads(RECORD.read_text())
    again = record_matrix()
    for role in ROLES:
        assert again[role] == committed[role], role
