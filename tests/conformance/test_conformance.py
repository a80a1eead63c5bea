"""Conformance: each probe node behaves under rosgrade as under Debian's real rospy with a Gazebo-like sim clock.

* ``test_same_as_real_rospy`` (realros): runs each probe under real ROS (real_ros.py) and under rosgrade
  (rosgrade_side.py) and compares stdout and stderr line by line (masked: see conformance_compare), sim times within
  one clock step, exit codes, and for publishing probes the /cmd_vel messages the robot received.
* ``test_reference_behaviour``: checks the behaviour values from the measured reference (probe_cases.py) on one side:
  on ours always, and on the real side too where real ROS is installed (which keeps the harness honest).

Each probe runs once per side per session (module-scoped caches). Real runs are real time; they share one rosmaster
and one sim and run one after another (about 25 s in all).
"""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from conformance_compare import diff_commands, diff_streams, missing_lines, normalise  # noqa: E402
from probe_cases import CASES, CASES_BY_ID, Case  # noqa: E402
from real_ros import NOT_INSTALLED, RealRos, RealRosError, real_ros_available  # noqa: E402
from rosgrade_side import run_ours  # noqa: E402

from tests.conformance_harness import (OurRuns, RealRuns, behaves_as_measured, exit_code,  # noqa: E402
                                       reference_time, same_as_real)

pytestmark = pytest.mark.slow


# Real rospy runs on wall time, so its timing varies from run to run (a SIGINT lands 20 ms late, a callback runs
# before the first /clock). Ours must match one of its outcomes: a probe is re-run under real ROS, up to this many
# times in all, before a difference counts.
REAL_ATTEMPTS = 3


def _run_real(ros: RealRos, case: Case):
    return ros.run_probe(case.path, case.args, shutdown_at=case.shutdown_at, duration=case.duration,
                         ros_namespace=case.ros_namespace)


def _run_ours(case: Case, workdir: Path):
    return run_ours(case.path, case.args, shutdown_at=case.shutdown_at, duration=case.duration,
                    ros_namespace=case.ros_namespace, workdir=workdir)


@pytest.fixture(scope="module")
def real_outputs(tmp_path_factory: pytest.TempPathFactory):
    """Real runs share one rosmaster and one sim (started with the first probe)."""
    if not real_ros_available():
        pytest.skip(NOT_INSTALLED)
    runs = RealRuns(lambda: RealRos(tmp_path_factory.mktemp("real") / "realros").__enter__(), _run_real,
                    RealRosError, REAL_ATTEMPTS)
    yield runs
    runs.close()


@pytest.fixture(scope="module")
def our_outputs(tmp_path_factory: pytest.TempPathFactory):
    return OurRuns(tmp_path_factory.mktemp("ours"), _run_ours)


@pytest.mark.realros
@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_same_as_real_rospy(case: Case, real_outputs: RealRuns, our_outputs: OurRuns) -> None:
    same_as_real(case, real_outputs, our_outputs.get(case), _differences, "rospy")


def _differences(case: Case, real, ours) -> list[str]:
    real_ref, our_ref = reference_time(real.stdout), reference_time(ours.stdout)
    problems = []
    problems += diff_streams("stdout", real.stdout, real_ref, ours.stdout, our_ref, case.tolerance_s)
    problems += diff_streams("stderr", real.stderr, real_ref, ours.stderr, our_ref, case.tolerance_s)
    if exit_code(real) != exit_code(ours):
        problems.append(f"exit code: real {exit_code(real)}, ours {exit_code(ours)}")
    if case.compare_commands:
        problems += diff_commands(real.commands, real_ref, ours.commands, our_ref, case.tolerance_s)
    return problems


def _check_reference(case: Case, result) -> list[str]:
    ref = reference_time(result.stdout)
    problems = [f"stdout lacks (in order): {line!r}" for line in missing_lines(list(case.stdout), result.stdout, ref)]
    problems += [f"stderr lacks (in order): {line!r}" for line in missing_lines(list(case.stderr), result.stderr, ref)]
    if case.stderr_empty and result.stderr.strip():
        problems.append(f"stderr should be empty, got: {[x.render() for x in normalise(result.stderr, ref)]}")
    if exit_code(result) != case.exit_code:
        problems.append(f"exit code {exit_code(result)}, expected {case.exit_code}")
    return problems


@pytest.mark.parametrize("side", ["ours", pytest.param("real", marks=pytest.mark.realros)])
@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_reference_behaviour(case: Case, side: str, request: pytest.FixtureRequest) -> None:
    if side == "ours":
        results = [request.getfixturevalue("our_outputs").get(case)]
    else:
        results = request.getfixturevalue("real_outputs").runs(case)
    behaves_as_measured(case, side, results, _check_reference)


def test_p10_command_stream_ours(our_outputs: OurRuns) -> None:
    """The robot receives the 10 Hz stream: iterations 1 and 2 at the same time, then 0.1 s apart (reference (a))."""
    case = next(c for c in CASES if c.id == "p10_publisher")
    result = our_outputs.get(case)
    ref = reference_time(result.stdout)
    received = {int(c.linear[2]): round(c.t - ref, 3) for c in result.commands}
    assert received.get(1) == received.get(2) == 0.0, received
    for i in range(3, 23):
        assert received.get(i) == pytest.approx(0.1 * (i - 2), abs=0.0101), (i, received)


def test_p03_last_command_is_zero_ours(our_outputs: OurRuns) -> None:
    """The zero Twist published in an on_shutdown hook reaches the robot (reference (b): delivered 15/15)."""
    case = next(c for c in CASES if c.id == "p03_shutdown_uncaught")
    result = our_outputs.get(case)
    assert result.commands, "no /cmd_vel received"
    last = result.commands[-1]
    assert last.linear == (0.0, 0.0, 0.0) and last.angular == (0.0, 0.0, 0.0), last


@pytest.mark.parametrize("mode, connect_s", [("busy", 0.1), ("sleep", 0.05)])
def test_p33_busy_connect_ours(our_outputs: OurRuns, mode: str, connect_s: float) -> None:
    """A publisher connects 0.1 s after it registered while the node busy-loops then, 50 ms while it sleeps
    (session.BUSY_CONNECT_DELAY_NS, CONNECT_DELAY_NS); the command published once connected reaches the robot then."""
    result = our_outputs.get(CASES_BY_ID[f"p33_busy_connect_{mode}"])
    ref = reference_time(result.stdout)
    assert f"{mode} wait for the robot ended t={connect_s:.3f}" in result.stdout.splitlines()
    assert [(round(c.t - ref, 2), c.linear) for c in result.commands] == [(connect_s, (0.2, 0.0, 0.0))]
