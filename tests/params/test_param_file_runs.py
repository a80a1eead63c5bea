"""A node started with --params-file reads its package's config/params.yaml inside its sandbox, and a file the grader
hands it by content (NodeSpec.files, as launch_ros's generated parameter files) overrides it: at a path that is the
same every run, so the recording repeats bit for bit."""
from __future__ import annotations

import hashlib
from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.confine import detect
from grader.runtime.session import Session
from grader.runtime.spec import file_arg
from sim import Scenario

PACKAGE = Path(__file__).resolve().parent / "pf_pkg"
NODE = PACKAGE / "pf_pkg" / "param_file_node.py"
CONFIG = PACKAGE / "config" / "params.yaml"
GENERATED = b"/mover:\n  ros__parameters:\n    name: launch\n    speed: 0.5\n"

pytestmark = pytest.mark.slow


def printed(tmp: Path, name: str, spec: NodeSpec) -> list[str]:
    session = Session(RunSpec(scenario=Scenario(robot="turtlesim", duration=2.0), nodes=(spec,)),
                      tmp / f"{name}.mcap", tmp / f"{name}.log")
    result = session.run()
    assert result.nodes[0].status == "exited" and result.nodes[0].exit_code == 0, result.nodes[0].message
    return [line[2] for line in Recording.open(tmp / f"{name}.mcap").output_lines() if line[1] == "stdout"]


@pytest.fixture(scope="module")
def runs(tmp_path_factory) -> tuple[Path, dict[str, list[str]]]:
    tmp = tmp_path_factory.mktemp("param_file_runs")
    given = NodeSpec(script=NODE, flavour="ros2", files=(("launch_params_0", GENERATED),),
                     args=("--ros-args", "--params-file", str(CONFIG), "--params-file", file_arg("launch_params_0")))
    return tmp, {"config": printed(tmp, "config", NodeSpec(script=NODE, flavour="ros2",
                                                           args=("--ros-args", "--params-file", str(CONFIG)))),
                 "first": printed(tmp, "first", given), "second": printed(tmp, "second", given)}


def test_the_packages_config_file_is_read_in_the_sandbox(runs) -> None:
    _tmp, out = runs
    assert out["config"][:4] == ["speed = 0.25", "name = 'first'", "waypoints = [0.5, 1.0]", "rate_hz = 10"]


def test_a_file_given_by_content_overrides_the_config_at_a_fixed_path(runs) -> None:
    tmp, out = runs
    assert out["first"][:4] == ["speed = 0.5", "name = 'launch'", "waypoints = [0.5, 1.0]", "rate_hz = 10"]
    inside = "/tmp/rosgrade-files/launch_params_0" if detect().namespaces else None
    files = out["first"][4]
    assert files.startswith("files [") and str(CONFIG) in files
    if inside is None:
        pytest.skip("no namespaces here: the node sees the file at its host path, which changes every run")
    assert inside in files
    digests = {hashlib.sha256((tmp / f"{name}.mcap").read_bytes()).hexdigest() for name in ("first", "second")}
    assert len(digests) == 1


def test_a_file_the_arguments_name_but_the_spec_does_not_give_is_refused() -> None:
    with pytest.raises(ValueError, match="name files it is not given"):
        NodeSpec(script=NODE, flavour="ros2", args=("--ros-args", "--params-file", file_arg("missing")))
