"""turtlesim conformance (issue 30): each turtlesim probe behaves under rosgrade as beside a real-rclpy turtlesim.

The real side is real_turtlesim2.py (a real-rclpy model of Jazzy's turtlesim_node) with the probes under real rclpy,
on turtlesim's interfaces built for real rclpy with build_turtlesim_interfaces.sh; ROSGRADE_TURTLESIM_INTERFACES
names that build's install folder. Comparison and reference checks are the ROS 2 suite's (test_conformance_ros2).
"""
from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from probe_cases2 import TURTLE_CASES, Case  # noqa: E402
from real_ros2 import RealRos2, RealRos2Error, unavailable_reason  # noqa: E402
from rosgrade_side2 import run_ours  # noqa: E402
from test_conformance_ros2 import REAL_ATTEMPTS, RETRY_PAUSE_S, _check_reference, _differences  # noqa: E402

from grader.rubric import GRADER_NODES  # noqa: E402
from tests.conformance_harness import OurRuns, RealRuns, behaves_as_measured, same_as_real  # noqa: E402

pytestmark = pytest.mark.slow
INTERFACES = Path(os.environ.get("ROSGRADE_TURTLESIM_INTERFACES", "/tmp/rosgrade-turtlesim-interfaces/build/install"))
MODEL = HERE / "real_turtlesim2.py"
IDS = [c.id for c in TURTLE_CASES]


def _real_reason() -> str | None:
    reason = unavailable_reason()
    if reason:
        return reason
    if not any(INTERFACES.glob("lib/python3*/site-packages/turtlesim/msg")):
        return (f"turtlesim's interfaces for real rclpy are not built at {INTERFACES}: run tests/conformance_ros2/"
                "build_turtlesim_interfaces.sh <build venv> <folder> and set ROSGRADE_TURTLESIM_INTERFACES to "
                "<folder>/build/install")
    return None


def _run_real(ros: RealRos2, case: Case):
    return ros.run_probe(case.path, case.args, shutdown_at=case.shutdown_at, duration=case.duration)


def _run_ours(case: Case, workdir: Path):
    return run_ours(case.path, case.args, shutdown_at=case.shutdown_at, duration=case.duration, workdir=workdir,
                    robot=case.world, beside=tuple(GRADER_NODES / script for script in case.beside))


@pytest.fixture(scope="module")
def real_outputs(tmp_path_factory: pytest.TempPathFactory):
    """Real runs share one model turtlesim (started with the first probe; each probe resets it)."""
    reason = _real_reason()
    if reason:
        pytest.skip(reason)
    runs = RealRuns(lambda: RealRos2(tmp_path_factory.mktemp("realturtle") / "realros2", robot_node=MODEL,
                                     interfaces=INTERFACES).__enter__(),
                    _run_real, RealRos2Error, REAL_ATTEMPTS, RETRY_PAUSE_S)
    yield runs
    runs.close()


@pytest.fixture(scope="module")
def our_outputs(tmp_path_factory: pytest.TempPathFactory):
    return OurRuns(tmp_path_factory.mktemp("oursturtle"), _run_ours)


@pytest.mark.realros
@pytest.mark.parametrize("case", TURTLE_CASES, ids=IDS)
def test_turtlesim_same_as_real(case: Case, real_outputs: RealRuns, our_outputs: OurRuns) -> None:
    same_as_real(case, real_outputs, our_outputs.get(case), _differences, "rclpy beside a real-rclpy turtlesim")


@pytest.mark.realros
@pytest.mark.parametrize("case", TURTLE_CASES, ids=IDS)
def test_turtlesim_reference_real(case: Case, real_outputs: RealRuns) -> None:
    behaves_as_measured(case, "real", real_outputs.runs(case), _check_reference)


@pytest.mark.parametrize("case", TURTLE_CASES, ids=IDS)
def test_turtlesim_reference_ours(case: Case, our_outputs: OurRuns) -> None:
    behaves_as_measured(case, "ours", [our_outputs.get(case)], _check_reference)
