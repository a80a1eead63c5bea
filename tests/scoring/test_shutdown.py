"""Shutdown response: zero command after Ctrl+C, time and distance to rest, how the node exited."""
from __future__ import annotations

import json
import math
from dataclasses import replace

import pytest
from scoring_synth import run

from grader.metrics import Commands, MetricError, RunData, RunInfo
from grader.metrics.shutdown import Params, measure

DRIVE = [(20.0, 0.1, 0.2)]


def _with_commands(data: RunData, commands: Commands) -> RunData:
    return RunData(data.odometry, data.ground_truth, commands, data.lines, data.run, data.start_time, data.shutdown_at)


def test_hook_that_publishes_zero_stops_the_robot() -> None:
    # Drive 20 s, Ctrl+C at 20 s, the hook's zero Twist 2 ms later, the robot at rest from 20.2 s.
    data = run(DRIVE + [(0.2, 0.05, 0.1), (5.0, 0.0, 0.0)], command_segments=DRIVE + [(0.002, 0.1, 0.2), (5.0, 0, 0)],
               info=RunInfo(shutdown_requested_s=20.0, exit_code=0, status="exited", ended_s=20.6), shutdown_at=20.0)
    m = measure(data, Params())
    assert m["zero_command_delay"] == pytest.approx(0.002, abs=1e-9)
    assert m["rest_time"] == pytest.approx(0.2, abs=0.04)
    assert m["rest_distance"] == pytest.approx(0.01, abs=0.003)
    assert m["moving_at_end"] is False and m["last_command_zero"] is True
    assert (m["exited"], m["exit_code"], m["status"]) == (True, 0, "exited")
    assert m["exit_delay"] == pytest.approx(0.6)


def test_hook_that_only_sets_a_flag_leaves_the_robot_moving() -> None:
    data = run(DRIVE + [(5.0, 0.1, 0.2)], command_segments=DRIVE,
               info=RunInfo(shutdown_requested_s=20.0, exit_code=1, status="exited", ended_s=20.7))
    m = measure(data, Params())
    assert math.isnan(m["zero_command_delay"]) and math.isnan(m["rest_time"])
    assert m["moving_at_end"] is True and m["last_command_zero"] is False
    assert m["observed_s"] == pytest.approx(5.0, abs=0.05)
    assert m["rest_distance"] == pytest.approx(0.5, abs=0.01)


def test_zero_then_motion_again_is_seen() -> None:
    data = run(DRIVE + [(5.0, 0.1, 0.2)], shutdown_at=20.0)
    cmds = Commands.of([19.9, 20.001, 20.05], [0.1, 0.0, 0.1], [0.2, 0.0, 0.2])
    m = measure(_with_commands(data, cmds), Params())
    assert m["zero_command_delay"] == pytest.approx(0.001) and m["last_command_zero"] is False


def test_planned_shutdown_time_is_used_when_the_run_did_not_record_one() -> None:
    data = run(DRIVE + [(5.0, 0.0, 0.0)], t0=40.0, shutdown_at=20.0)
    m = measure(data, Params())
    assert m["rest_time"] == pytest.approx(0.0) and m["exited"] is False


def test_robot_that_never_moved_and_heard_nothing_after_ctrl_c_proves_nothing() -> None:
    with pytest.raises(MetricError, match="before Ctrl\\+C"):
        measure(run([(10.0, 0.0, 0.0)], command_segments=[(4.0, 0.0, 0.0)], shutdown_at=5.0), Params())


def test_robot_at_rest_that_gets_a_zero_after_ctrl_c_has_stopped() -> None:
    m = measure(run([(10.0, 0.0, 0.0)], shutdown_at=5.0), Params())
    assert m["rest_time"] == 0.0 and m["zero_command_delay"] == 0.0 and m["moving_at_end"] is False


def test_a_zero_the_base_ignores_is_no_stop_of_a_robot_that_never_moved() -> None:
    data = replace(run([(10.0, 0.0, 0.0)], shutdown_at=5.0), ignored_command_types="geometry_msgs/Twist")
    with pytest.raises(MetricError, match="before Ctrl\\+C"):
        measure(data, Params())


def test_run_info_from_json_metadata() -> None:
    meta = {"rosgrade.run": {"shutdown_requested_s": "20.5", "exit_code": "-2", "exit_signal": '"SIGINT"',
                             "status": '"killed"', "ended_s": "null"}}
    info = RunInfo.from_metadata(meta)
    assert info == RunInfo(shutdown_requested_s=20.5, exit_code=-2, exit_signal="SIGINT", status="killed")
    nested = {"rosgrade.run": {"json": json.dumps({"shutdown_requested_s": 3.0, "exit_code": 0})}}
    assert RunInfo.from_metadata(nested).shutdown_requested_s == 3.0
