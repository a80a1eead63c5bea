"""A confined node imports the Python packages its workspace installs, its own and another package's, and nothing
of them without the workspace's import roots (the ModuleNotFoundError a COM2009-template node used to get)."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec, confine
from grader.runtime.client_library import import_roots
from grader.runtime.session import run
from grader.workspace import read_workspace
from sim import Scenario

from workspace_helpers import cmake_package, write

pytestmark = pytest.mark.slow

NODE = """#!/usr/bin/env python3
import rclpy
from part2_navigation_modules.tb3_tools import quaternion_to_euler
from team_tools_modules import words

rclpy.init()
print(words.GREETING, quaternion_to_euler(7))
rclpy.shutdown()
"""


def _run(tmp_path: Path, with_roots: bool) -> str:
    src = tmp_path / "ws" / "src"
    nav = cmake_package(src / "part2_navigation")
    tools = cmake_package(src / "team_tools", "team_tools")
    write(tools / "team_tools_modules" / "words.py", "GREETING = 'hello from team_tools'\n")
    script = write(nav / "scripts" / "move_circle.py", NODE)
    spec = NodeSpec(script=script, flavour="ros2",
                    import_roots=import_roots(script, read_workspace(tmp_path / "ws")) if with_roots else ())
    run(RunSpec(scenario=Scenario(duration=1.0), nodes=(spec,)), tmp_path / "run.mcap", tmp_path / "run.log")
    return "\n".join(text for _, _, text in Recording.open(tmp_path / "run.mcap").output_lines())


@pytest.fixture(params=["detected", "unshare"])
def isolation(request, monkeypatch):
    """The isolation this machine gives nodes, then namespaces via unshare (the fallback without bubblewrap)."""
    if request.param == "unshare":
        unshare, root = shutil.which("unshare"), confine.detect().root
        why = "util-linux unshare is not installed" if unshare is None else confine._probe_unshare(unshare, root)
        if why:
            pytest.skip(f"no namespaces via unshare here: {why}")
        monkeypatch.setattr(confine, "_capability", confine.Capability(None, root, unshare=unshare))
    return confine.detect().isolation


def test_the_node_imports_its_own_and_another_package_s_modules(tmp_path: Path, isolation: str) -> None:
    assert "hello from team_tools 7" in _run(tmp_path, True), isolation


def test_a_bubblewrap_sandbox_shows_import_roots_outside_the_node_s_package(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setattr(confine, "_capability", confine.Capability("/usr/bin/bwrap", False))
    package, other = cmake_package(tmp_path / "a", "a"), cmake_package(tmp_path / "b", "b")
    script = package / "scripts" / "move_circle.py"
    argv = confine.plan(["-B", str(script)], script, tmp_path / "home", 16,
                        (package, other, tmp_path / "missing")).argv
    binds = [argv[i + 1:i + 3] for i, arg in enumerate(argv) if arg == "--ro-bind"]
    assert [str(other), str(other)] in binds and [str(package), str(package)] in binds
    assert binds.index([str(other), str(other)]) < binds.index([str(package), str(package)])
    assert not [b for b in binds if "missing" in b[0]]


def test_without_the_workspace_s_roots_the_modules_are_not_found(tmp_path: Path) -> None:
    assert "No module named 'part2_navigation_modules'" in _run(tmp_path, False)
