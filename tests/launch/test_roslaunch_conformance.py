"""`rosgrade launch --dump-params / --nodes` print what Debian's real roslaunch prints for the same launch files.

Each case runs real `roslaunch` (with ROS_PACKAGE_PATH on the test workspace) and rosgrade's reader on the same
file and args and compares stdout byte for byte. Error cases must be errors on both sides. `$(anon)` names are
random in real roslaunch (host, pid, random number), so their suffix is compared by shape only.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from grader.launch import LaunchError, dump_params, find_packages, node_names, read_launch
from grader.launch.specs import node_specs

WORKSPACE = Path(__file__).parent / "ws" / "src"
CASES = WORKSPACE / "launch_cases" / "launch"
ENV = {"ROSGRADE_CASE_VAR": "from env", "ROSGRADE_CASE_MODEL": "burger"}
ROSLAUNCH = shutil.which("roslaunch")
ANON_SUFFIX = re.compile(r"_[A-Za-z0-9_]+?_\d+_\d+\b")

SUCCESS_CASES = [
    ("args.launch", {}),
    ("args.launch", {"distance": "5", "speed": "0.1"}),
    ("types.launch", {}),
    ("rosparam.launch", {}),
    ("rosparam.launch", {"rate": "20"}),
    ("namespaces.launch", {}),
    ("conditions.launch", {}),
    ("conditions.launch", {"teleop": "1", "mode": "triangle", "use_group": "false"}),
    ("conditions.launch", {"teleop": "true"}),
    ("substitutions.launch", {}),
    ("include_top.launch", {}),
    ("include_top.launch", {"distance": "9", "who": "cli"}),
    ("seed000_both.launch", {}),
    ("empty.launch", {}),
    ("anon.launch", {}),
    ("scopes.launch", {}),
    ("scopes.launch", {"speed": "0.05"}),
    ("turtlesim.launch", {}),
    ("turtlesim.launch", {"teleop": "1"}),
]
ERROR_CASES = [
    ("errors/unused_include_arg.launch", {}),
    ("errors/bad_if.launch", {}),
    ("errors/duplicate_arg.launch", {}),
    ("errors/syntax.launch", {}),
    ("errors/unknown_substitution.launch", {}),
    ("errors/undeclared_arg.launch", {}),
    ("errors/missing_include.launch", {}),
    ("errors/unknown_package.launch", {}),
    ("errors/both_value_default.launch", {}),
    ("passed.launch", {}),  # required args not passed
    ("args.launch", {"fixed": "1"}),  # an arg with value= cannot be overridden
]


def _ids(cases: list[tuple[str, dict[str, str]]]) -> list[str]:
    return [name + "".join(f"-{k}={v}" for k, v in args.items()) for name, args in cases]


ARGS_CASES = [("args.launch", {"speed": "0.1"}), ("namespaces.launch", {}), ("include_top.launch", {}),
              ("seed000_both.launch", {}), ("scopes.launch", {})]


def _real(mode: str, name: str, args: dict[str, str]) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, **ENV, "ROS_PACKAGE_PATH": str(WORKSPACE), "ROS_HOME": os.environ.get("TMPDIR", "/tmp")}
    env.pop("ROSGRADE_CASE_UNSET", None)
    command = [ROSLAUNCH, *mode.split(" ", 1), str(CASES / name), *(f"{k}:={v}" for k, v in args.items())]
    return subprocess.run(command, capture_output=True, text=True, env=env, timeout=60)


def _ours(mode: str, name: str, args: dict[str, str]) -> str:
    env = {k: v for k, v in os.environ.items() if k != "ROSGRADE_CASE_UNSET"} | ENV
    launch = read_launch(CASES / name, args, find_packages(WORKSPACE), env)
    return dump_params(launch) if mode == "--dump-params" else node_names(launch)


needs_roslaunch = pytest.mark.skipif(ROSLAUNCH is None, reason="real roslaunch is not installed "
                                     "(Debian: apt-get install python3-roslaunch)")


@pytest.mark.realros
@needs_roslaunch
@pytest.mark.parametrize("mode", ["--dump-params", "--nodes"])
@pytest.mark.parametrize(("name", "args"), SUCCESS_CASES, ids=_ids(SUCCESS_CASES))
def test_same_output_as_roslaunch(mode: str, name: str, args: dict[str, str]) -> None:
    real = _real(mode, name, args)
    assert real.returncode == 0 and not real.stderr.strip(), real.stderr
    ours = _ours(mode, name, args)
    if name == "anon.launch":
        assert ANON_SUFFIX.sub("_ANON", ours) == ANON_SUFFIX.sub("_ANON", real.stdout)
    else:
        assert ours == real.stdout


@pytest.mark.realros
@needs_roslaunch
@pytest.mark.parametrize(("name", "args"), ERROR_CASES, ids=_ids(ERROR_CASES))
def test_same_errors_as_roslaunch(name: str, args: dict[str, str]) -> None:
    real = _real("--nodes", name, args)
    assert real.returncode != 0 and real.stdout == "", real.stdout
    with pytest.raises(LaunchError):
        _ours("--nodes", name, args)


@pytest.mark.realros
@needs_roslaunch
@pytest.mark.parametrize(("name", "args"), ARGS_CASES, ids=_ids(ARGS_CASES))
def test_each_node_gets_the_command_line_and_namespace_roslaunch_gives_it(name: str, args: dict[str, str]) -> None:
    """`roslaunch --args NODE` prints the node's environment and command line: the runtime's NodeSpec must match."""
    packages = find_packages(WORKSPACE)
    launch = read_launch(CASES / name, args, packages, ENV)
    specs, _ = node_specs(launch, packages)
    for node, spec in zip(launch.nodes, specs):
        real = _real(f"--args {node.full_name}", name, args)
        assert real.returncode == 0, real.stderr
        namespace = f'ROS_NAMESPACE="{spec.ros_namespace}" ' if spec.ros_namespace else ""
        ours = f'ROS_MASTER_URI="http://localhost:11311/" {namespace}{spec.script} {" ".join(spec.args)}'
        assert ours == real.stdout.strip()
