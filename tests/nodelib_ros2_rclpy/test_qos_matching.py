"""rosgrade's rclpy matches publishers and subscriptions by reliability and durability as real rclpy does.

The target is tests/conformance_ros2/qos_matrix_jazzy.json, recorded with record_qos_matrix.py from two real Jazzy
nodes: one publisher per offered QoS, one subscription per requested QoS, created before discovery (``sub``, as in
a node's constructor) or after it (``sub_discovered``). Each pair is a topic; the record says whether anything
arrived and which "incompatible QoS" warnings the subscriber logged.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.nodelib_ros2_rclpy import ros2_grader  # noqa: F401 - puts the ROS 2 import roots on sys.path

from rclpy.qos import (DurabilityPolicy, QoSProfile, ReliabilityPolicy, incompatible_policy,  # noqa: E402
                       incompatible_qos_warning, offered_policies, requested_policies)

RECORD = json.loads((Path(__file__).resolve().parents[1] / "conformance_ros2" / "qos_matrix_jazzy.json").read_text())
# The record's topic names shorten each policy to its first and last two letters (qos_matrix_node.topic).
_SHORT = {p[:2] + p[-2:]: p for p in ("reliable", "best_effort", "best_available", "system_default", "volatile",
                                      "transient_local")}


def _pair(name: str) -> tuple[tuple[str, str], tuple[str, str]]:
    """((offered reliability, durability), (requested ...)) of a record's topic name."""
    r1, d1, r2, d2 = (_SHORT[key] for key in name.removeprefix("/qos_").split("_"))
    return (r1, d1), (r2, d2)


def _profile(reliability: str, durability: str) -> QoSProfile:
    return QoSProfile(depth=10, reliability=ReliabilityPolicy[reliability.upper()],
                      durability=DurabilityPolicy[durability.upper()])


@pytest.mark.parametrize("role", ["sub", "sub_discovered"])
def test_matching_as_recorded(role: str) -> None:
    """Every (offered, requested) pair is received, or warned about, exactly as under real rclpy."""
    received, warnings = {}, set()
    assert len(RECORD[role]["received"]) == 9 * 16
    for name in RECORD[role]["received"]:
        offered, requested = _pair(name)
        offers = offered_policies(_profile(*offered))
        discovered = [offers] if role == "sub_discovered" else []
        policy = incompatible_policy(offers, requested_policies(_profile(*requested), discovered))
        received[name] = policy is None
        if policy is not None:
            warnings.add(incompatible_qos_warning(name, policy))
    assert received == RECORD[role]["received"]
    assert sorted(warnings) == RECORD[role]["subscription_warnings"]


def test_sensor_data_against_a_reliable_publisher() -> None:
    """The course's fix: qos_profile_sensor_data hears a RELIABLE publisher and a BEST_EFFORT one alike."""
    from rclpy.qos import qos_profile_sensor_data
    wanted = requested_policies(qos_profile_sensor_data, [])
    for offered in ((ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE),
                    (ReliabilityPolicy.BEST_EFFORT, DurabilityPolicy.VOLATILE)):
        assert incompatible_policy(offered, wanted) is None
