"""Whole runs through the lockstep loop: determinism, busy loops, arguments and stdin, recorded outcomes."""
from __future__ import annotations

import hashlib
import multiprocessing
import os
import platform
from pathlib import Path

import numpy as np
import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec, cpu_claim
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
    "control loop in a student thread": (NODES / "thread_controller.py", Scenario(duration=6.0, shutdown_at=5.0)),
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
    # init_node takes 0.1 s; the next /odom is due 33 ms later and the wait ends on the next clock tick after it.
    assert t == pytest.approx(scenario_start() + 0.14) and abs(float(text.split("=")[1])) < 1e-9
    assert rec.commands().wz.max() == pytest.approx(0.5)


def test_student_thread_drives_the_robot_in_sim_time(tmp_path):
    result, rec = run_node(tmp_path, NODES / "thread_controller.py", Scenario(duration=6.0, shutdown_at=5.0))
    assert result.nodes[0].status == "exited" and result.nodes[0].exit_code == 0
    commands = rec.commands()
    moving = commands.t[commands.vx > 0]
    # 10 Hz from the thread's Rate: 0.5 m at 0.2 m/s is about 25 commands, 0.1 s apart
    assert 20 <= len(moving) <= 30 and np.allclose(np.diff(moving), 0.1, atol=0.011)
    assert commands.vx[-1] == 0.0
    assert 0.5 <= rec.ground_truth().x[-1] <= 0.6
    assert any(text.startswith("stopped at x=0.5") for _, _, text in rec.output_lines())


@pytest.mark.parametrize("kind", ["Lock", "RLock"])
def test_a_lock_held_across_a_sleep_makes_the_others_wait_without_deadlock(tmp_path, kind):
    """Locks, and the SimpleQueue a ThreadPoolExecutor's workers wait on, wait through the scheduler."""
    result, rec = run_node(tmp_path, NODES / "lock_across_sleep.py", Scenario(duration=4.0), args=(kind,))
    assert result.nodes[0].exit_code == 0, result.nodes[0].message
    assert [text for _, stream, text in rec.output_lines() if stream == "stdout"] == [
        "thread 5 main > 5 True odom > 20 True", "executor 42"]
    assert result.wall_s < 3.0


@pytest.mark.parametrize("script", ["latched_once.py", "connection_wait.py"])
def test_a_single_command_drives_the_robot_when_latched_or_sent_once_connected(tmp_path, script):
    """Issue 9 items 1-2: as on real ROS, one latched Twist published at once, or one sent after waiting for
    get_num_connections(), reaches the robot, which then drives at 0.2 m/s until the end of the run."""
    result, rec = run_node(tmp_path, NODES / script, Scenario(duration=3.0))
    commands = rec.commands()
    assert len(commands) == 1 and commands.vx[0] == pytest.approx(0.2)
    assert commands.callerid[0] == "/" + script.removesuffix(".py")
    assert rec.ground_truth().x[-1] - rec.ground_truth().x[0] > 0.4
    # the latched message waited for the connection: nothing was lost, and the diagnostics say nothing about it
    assert not [t.topic for t in rec.topics() if t.topic.startswith("/rosgrade/lost")]
    assert not [note for note in result.diagnostics if "lost" in note]
    # the recording marks the channel as latched as real bags do (the ROS 1 connection header's "1"/"0")
    from mcap.reader import make_reader
    with open(tmp_path / "run.mcap", "rb") as f:
        channels = make_reader(f).get_summary().channels.values()
    latching = {c.metadata["latching"] for c in channels if c.topic == "/cmd_vel"}
    assert latching == {"1" if script == "latched_once.py" else "0"}


def test_other_clocks_and_timed_waits_follow_sim_time(tmp_path):
    """asyncio.sleep, Event.wait, select and poll timeouts wait in sim time (no wall time burned); datetime.now and
    time.localtime, clock_gettime and os.times' elapsed read sim time (issue 17)."""
    result, rec = run_node(tmp_path, NODES / "realtime_clocks.py", Scenario(duration=4.0))
    assert result.nodes[0].exit_code == 0, result.nodes[0].message
    lines = [text for _, stream, text in rec.output_lines() if stream == "stdout"]
    assert lines == ["asyncio.sleep(0.5) 0.5 0.5", "Event().wait(0.3) 0.3 0.3", "select 0.2 0.2 0.2", "poll 200 ms 0.2 0.2",
                     "datetime is the stdlib's True True", "datetime.now matches time.time True",
                     "localtime matches time.time True", "clock_gettime matches True True",
                     "os.times elapsed matches True"]
    assert result.wall_s < 3.0


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


@pytest.fixture(scope="module")
def cpu_view_log(tmp_path_factory) -> str:
    """The log of one run of a node that prints the CPUs and scheduling policy it sees and the kernel gives it."""
    tmp = tmp_path_factory.mktemp("cpu_view")
    # CPU claims of its own: other graders on this machine (a parallel test run, a batch) could hold every CPU's
    # claim, and the run would rightly go unpinned.
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(cpu_claim, "_lock_folder", lambda: tmp)
        run_node(tmp, NODES / "cpu_view.py", Scenario(duration=1.0))
    return (tmp / "run.log").read_text()


def _printed(log: str, label: str) -> str:
    return next(line.split(f"{label} ")[1] for line in log.splitlines() if f"{label} " in line)


def test_the_node_runs_on_its_runs_cpu_but_sees_four(cpu_view_log):
    assert "sees 4 4 [0, 1, 2, 3]" in cpu_view_log
    kernel = _printed(cpu_view_log, "kernel")
    if len(os.sched_getaffinity(0)) >= 2:
        assert kernel.isdigit(), f"the node may use CPUs {kernel}, not the one its run claimed"


def test_the_node_is_a_batch_task_whose_wake_ups_do_not_preempt_the_grader(cpu_view_log):
    assert _printed(cpu_view_log, "policy") == str(os.SCHED_BATCH)


@pytest.mark.skipif(platform.machine() != "x86_64", reason="the baseline kernels are chosen on x86-64 only")
def test_the_nodes_numpy_runs_its_baseline_kernels_on_every_cpu(cpu_view_log):
    # Not AVX-512's arctan2 or an FMA dot product: the same bits on every x86-64 grader.
    assert _printed(cpu_view_log, "arctan2").startswith("baseline")
    core, dot = _printed(cpu_view_log, "blas").split()
    assert core == "Sandybridge"
    assert float.fromhex(dot) == ((0.1 * 0.3 + 0.2 * 0.9) + 0.3 * 0.5) + 0.7 * 0.1
