"""Whole runs of a rospy node against turtlesim: it sees turtle1/pose, drives turtle1/cmd_vel, recordings repeat."""
from __future__ import annotations

import hashlib
import math
from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

GO_TO_GOAL = Path(__file__).resolve().parents[2] / "reference_solutions_turtlesim" / "go_to_goal.py"

pytestmark = pytest.mark.slow


def run_goal(tmp: Path, name: str, goal: str = "8.0\n2.0\n") -> tuple[object, Recording]:
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=12.0), nodes=(NodeSpec(script=GO_TO_GOAL, stdin=goal),))
    result = run(spec, tmp / f"{name}.mcap", tmp / f"{name}.log")
    return result, Recording.open(tmp / f"{name}.mcap")


@pytest.fixture(scope="module")
def goal_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("turtlesim")
    result, rec = run_goal(tmp, "first")
    return tmp, result, rec


def test_a_pose_following_node_reaches_its_goal(goal_run):
    _, result, rec = goal_run
    assert result.nodes[0].status == "exited", result.nodes[0].message
    poses = list(rec.messages("/turtle1/pose"))
    assert len(poses) >= 12.0 / 0.016 - 2
    final = poses[-1][1]
    assert math.hypot(final.x - 8.0, final.y - 2.0) < 0.06
    assert final.linear_velocity == 0.0


def test_the_recording_holds_the_commands_and_ground_truth(goal_run):
    _, _, rec = goal_run
    assert rec.commands().vx.max() > 0
    truth = rec.ground_truth()
    assert truth.x[-1] == pytest.approx(8.0, abs=0.06)


def test_turtlesim_recordings_are_bit_identical_on_repeat(goal_run):
    tmp, _, _ = goal_run
    run_goal(tmp, "second")
    digest = [hashlib.sha256((tmp / f"{n}.mcap").read_bytes()).hexdigest() for n in ("first", "second")]
    assert digest[0] == digest[1]
