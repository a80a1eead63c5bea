"""rospy's set_param and delete_param against a stand-in grader: each change the node makes is one PARAM frame with
the resolved name and the value as rosmaster stores it; failed calls and values JSON cannot carry send nothing."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.nodelib.fake_grader import FakeGrader

PROBE = Path(__file__).resolve().parent / "nodes" / "param_probe.py"


@pytest.fixture(scope="module")
def probe_run():
    run = FakeGrader(str(PROBE), params={"/use_sim_time": True, "/given": {"a": [1, 2]}}, end_ns=3_000_000_000,
                     timeout_s=20.0).run()
    assert run.returncode == 0, run.raw_stderr.decode()
    return run


def test_each_change_is_one_param_frame_with_the_resolved_name(probe_run) -> None:
    assert [f.data for f in probe_run.of("PARAM")] == [
        {"op": "set", "name": "/before_init", "value": 1},
        {"op": "set", "name": "/probe/rate", "value": 5},  # init_node's _rate:=5
        {"op": "set", "name": "/probe/gain", "value": [1, 2.5]},
        {"op": "set", "name": "/plain", "value": {"x": "y"}},
        {"op": "delete", "name": "/plain/x"},
    ]


def test_the_node_reads_its_own_changes_and_starts_ones_at_once(probe_run) -> None:
    lines = probe_run.lines()
    assert "missing '/missing'" in lines and "none refused" in lines
    assert "gain [1, 2.5] plain {} blob True" in lines
    assert "start {'a': [1, 2]}" in lines
