"""Runs with nothing to measure get a verdict in words that fit them, not "could not measure" or "0 of 0"."""
from __future__ import annotations

from dataclasses import replace

import pytest
from scoring_synth import run

from grader.metrics import Commands, RunData, RunInfo
from grader.reports.measured import describe
from grader.rubric import load_rubrics
from grader.scoring import score_task

RUBRICS = load_rubrics()
VELOCITY_TASKS = sorted(t for t, r in RUBRICS.items() if any(c.id == "velocity_limits" for c in r.criteria))


def _criterion(task: str, runs: dict[str, RunData], criterion: str):
    return next(c for c in score_task(RUBRICS[task], runs).criteria if c.id == criterion)


def _still(task: str, commands: Commands) -> dict[str, RunData]:
    """Every scenario of ``task`` with the robot at rest throughout and the node's ``commands``."""
    runs = {}
    for s in RUBRICS[task].scenarios:
        shutdown = None if s.shutdown_at is None else s.start_time + s.shutdown_at
        data = run([(s.duration, 0.0, 0.0)], t0=s.start_time, shutdown_at=s.shutdown_at,
                   info=RunInfo(shutdown_requested_s=shutdown, exit_code=0, status="exited"))
        runs[s.name] = replace(data, commands=commands)
    return runs


@pytest.mark.parametrize("task", VELOCITY_TASKS)
def test_a_node_that_published_no_command_is_told_so(task: str) -> None:
    limits = _criterion(task, _still(task, Commands.empty()), "velocity_limits")
    assert limits.score == 0.0
    assert "published no velocity command" in limits.feedback and "0 of 0" not in limits.feedback
    assert "0 of 0" not in describe(limits.measured)  # the report's Measured column


@pytest.mark.parametrize("task", ["move_circle", "mover_timed_square"])
def test_a_zero_after_ctrl_c_with_the_robot_at_rest_is_a_stop(task: str) -> None:
    runs = {name: replace(data, commands=Commands.of([data.shutdown_time() + 0.01], [0.0], [0.0]))
            for name, data in _still(task, Commands.empty()).items()}
    stop = _criterion(task, runs, "shutdown_stop")
    assert stop.score == stop.max_score, stop.feedback
    assert "Could not measure" not in stop.feedback and "at rest" in stop.feedback


def test_a_robot_at_rest_whose_node_sent_nothing_after_ctrl_c_shows_no_stop() -> None:
    task = "move_circle"
    before = Commands.of([2.5], [0.0], [0.0])  # a zero at the start only
    stop = _criterion(task, _still(task, before), "shutdown_stop")
    assert stop.score == 0.0 and "before Ctrl+C" in stop.feedback


def test_a_zero_the_robot_does_not_take_is_no_stop() -> None:
    task = "move_circle"
    runs = {name: replace(data, commands=Commands.of([data.shutdown_time() + 0.01], [0.0], [0.0]),
                          ignored_command_types="geometry_msgs/Twist")
            for name, data in _still(task, Commands.empty()).items()}
    assert _criterion(task, runs, "shutdown_stop").score == 0.0
