"""rosgrade_rosidl's CDR bytes equal rosbags' serialize_cdr for random values of every covered type (cdr_battery.py)."""
from __future__ import annotations

import pytest

from .helpers import covered_types, run_json

SEEDS = 5


@pytest.fixture(scope="module")
def battery() -> dict:
    return run_json(["cdr_battery.py", str(SEEDS)])


@pytest.mark.parametrize("type_name", covered_types())
def test_bytes_round_trip_and_truncation_match_rosbags(battery, type_name):
    assert battery[type_name] == "ok"
