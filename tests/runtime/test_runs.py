"""Whole runs through the lockstep loop: determinism, busy loops, arguments and stdin, recorded outcomes."""
from __future__ import annotations

import hashlib
import multiprocessing
from pathlib import Path

import numpy as np
import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Pose2D, Scenario

NODES = Path(__file__).parent / "nodes"
REFERENCE = Path(__file__).resolve().parents[2] / "reference_solutions"

pytestmark = pytest.mark.slow


def _spin(stop) -> None:
    while not stop.is_set():
        pass


def run_node(tmp: Path, script: Path, scenario: Scenario, *, args=(), stdin=None, name="run"):
    spec = RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, args=tuple(args), stdin=stdin),))
    result = run(spec, tmp / f"{name}.mcap", tmp / f"{name}.log")
    return result, Recording.open(tmp / f"{name}.mcap")


def scenario_start() -> float:
    return Scenario().start_time


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


DETERMINISM_CASES = {
    "odometry square (callbacks + rate)": (REFERENCE / "move_square.py",
                                          Scenario(duration=30.0, initial_pose=Pose2D(x=-2.0, y=-0.5, yaw=2.96706))),
    "busy publisher": (NODES / "busy_publisher.py", Scenario(duration=12.0)),
    "pure-Python busy wait": (NODES / "busy_wait_first_odom.py", Scenario(duration=5.0)),
}


@pytest.mark.parametrize("case", sorted(DETERMINISM_CASES))
def test_recording_is_bit_identical_even_with_the_other_core_busy(tmp_path, case):
    script, scenario = DETERMINISM_CASES[case]
    first, _ = run_node(tmp_path, script, scenario, name="first")
    stop = multiprocessing.Event()
    hog = multiprocessing.Process(target=_spin, args=(stop,))
    hog.start()
    try:
        second, _ = run_node(tmp_path, script, scenario, name="second")
    finally:
        stop.set()
        hog.join()
    assert digest(tmp_path / "first.mcap") == digest(tmp_path / "second.mcap")
    assert first.nodes[0] == second.nodes[0]


def test_busy_loop_advances_sim_time_and_sees_odometry(tmp_path):
    result, rec = run_node(tmp_path, NODES / "busy_publisher.py", Scenario(duration=12.0))
    assert result.nodes[0].status == "exited" and result.nodes[0].exit_code == 0
    commands = rec.commands()
    moving = commands.vx > 0
    # Every library call costs 1 ms of sim time, so publishing with no sleep still lets the robot reach 1.5 m.
    assert 200 <= moving.sum() <= 5000
    assert commands.vx[-1] == 0.0
    truth = rec.ground_truth()
    assert 1.5 <= truth.x[-1] <= 1.6
    assert any("stopped at x=1.5" in text for _, _, text in rec.output_lines())


def test_pure_busy_wait_ends_when_the_callback_sets_the_value(tmp_path):
    result, rec = run_node(tmp_path, NODES / "busy_wait_first_odom.py", Scenario(duration=5.0))
    assert result.nodes[0].exit_code == 0
    (t, _, text), = [line for line in rec.output_lines() if line[2].startswith("first odom")]
    # The first /odom is due 33 ms after the start; the wait ends on the next clock tick after it.
    assert t == pytest.approx(scenario_start() + 0.04) and abs(float(text.split("=")[1])) < 1e-9
    assert rec.commands().wz.max() == pytest.approx(0.5)


def test_arguments_remapping_and_stdin_reach_the_node(tmp_path):
    result, rec = run_node(tmp_path, NODES / "stdin_args.py", Scenario(duration=4.0),
                           args=("0.15", "cmd_vel:=/remapped"), stdin="0.1\n")
    lines = [text for _, stream, text in rec.output_lines() if stream == "stdout"]
    assert "argv ['0.15', 'cmd_vel:=/remapped']" in lines
    assert "myargv ['0.15']" in lines
    assert {t.topic for t in rec.topics() if t.type == "geometry_msgs/Twist"} == {"/remapped"}
    # Nothing reached the robot's /cmd_vel: the diagnostics say where the commands went.
    assert any("published 2 messages on /remapped" in note and "listens on /cmd_vel" in note
               for note in result.diagnostics)


def test_run_metadata_records_exit_and_shutdown(tmp_path):
    scenario = Scenario(duration=8.0, shutdown_at=5.0)
    result, rec = run_node(tmp_path, REFERENCE / "move_circle.py", scenario)
    run_info = rec.metadata["rosgrade.run"]
    assert run_info["shutdown_requested_s"] == pytest.approx(scenario.start_time + 5.0)
    assert run_info["exit_code"] == 0 and run_info["status"] == "exited"
    # The hook's zero Twist is the last command, sent at the Ctrl+C time.
    commands = rec.commands()
    assert commands.vx[-1] == 0.0 and commands.t[-1] == pytest.approx(scenario.start_time + 5.0)
    assert np.all(commands.t[:-1] < scenario.start_time + 5.0)
