"""Runs probes.py and serialize_probes.py under real ROS 2 (rosidl_generator_py, rclpy) and under rosgrade; they match."""
from __future__ import annotations

import json

import pytest

from .helpers import REAL_PYTHON, covered_types, real_venv_reason, run, run_json

REAL_PACKAGES = ("builtin_interfaces", "std_msgs", "geometry_msgs", "nav_msgs", "sensor_msgs", "rosgraph_msgs",
                 "rcl_interfaces")

pytestmark = [pytest.mark.realros, pytest.mark.skipif(real_venv_reason() is not None, reason=str(real_venv_reason()))]


@pytest.fixture(scope="module")
def types_file(tmp_path_factory) -> str:
    path = tmp_path_factory.mktemp("ros2") / "types.json"
    path.write_text(json.dumps([t for t in covered_types() if t.split("/")[0] in REAL_PACKAGES]))
    return str(path)


def _lines(text: str) -> dict:
    return dict(json.loads(line) for line in text.splitlines())


@pytest.mark.parametrize("check_fields", ["", "1"], ids=["default", "ROS_PYTHON_CHECK_FIELDS=1"])
def test_every_behaviour_probe_matches_real_rosidl(types_file, check_fields):
    env = {"ROS_PYTHON_CHECK_FIELDS": check_fields}
    real = _lines(run(["probes.py", types_file], python=str(REAL_PYTHON), ours=False, env=env))
    ours = _lines(run(["probes.py", types_file], env=env))
    assert real.keys() == ours.keys()
    mismatches = [f"{k}\n  real: {real[k]}\n  ours: {ours[k]}" for k in real if real[k] != ours[k]]
    assert not mismatches, f"{len(mismatches)} of {len(real)} probes differ:\n" + "\n".join(mismatches[:30])


def test_serialization_matches_real_rclpy(types_file, tmp_path):
    real_out = tmp_path / "real.jsonl"
    real_out.write_text(run(["serialize_probes.py", "real", types_file], python=str(REAL_PYTHON), ours=False))
    results = run_json(["serialize_probes.py", "ours", str(real_out)])
    bad = {k: v for k, v in results.items() if v != "ok"}
    assert len(results) > 100
    assert not bad, "\n".join(f"{k}: {v}" for k, v in bad.items())
