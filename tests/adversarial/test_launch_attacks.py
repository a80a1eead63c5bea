"""Hostile ROS 2 launch files: each gets a clear finding in bounded time, and nothing outside the sandbox changes."""
from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from grader.launch.ros2_eval import LIMITS, Ros2LaunchError, evaluate
from grader.runtime import confine
from grader.runtime.spec import Limits
from grader.workspace import read_workspace

PACKAGE_XML = ('<?xml version="1.0"?><package format="3"><name>evil_pkg</name><version>0.0.0</version>'
               '<description>x</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>'
               '<export><build_type>ament_python</build_type></export></package>')
# The grader's limits, with a shorter wall time and CPU time so that the endless loop costs the suite 3 s, not 20.
SHORT = Limits(wall_s=3.0, cpu_s=2.0, memory_mb=LIMITS.memory_mb, processes=LIMITS.processes, file_mb=LIMITS.file_mb)
HEAD = "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
ATTACKS = {
    "loop": HEAD + "def generate_launch_description():\n    while True:\n        pass\n",
    "self_include": HEAD + (
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([IncludeLaunchDescription(PythonLaunchDescriptionSource(__file__))])\n"),
    "many_nodes": HEAD + ("def generate_launch_description():\n    return LaunchDescription(["
                          "Node(package='turtlesim', executable='turtlesim_node', name=f'n{i}')\n"
                          "        for i in range(10000)])\n"),
    "absent_import": "import com2009_secret_helpers\n" + HEAD,
    "write_outside": HEAD + ("def generate_launch_description():\n"
                             "    open({target!r}, 'w').write('pwned')\n    return LaunchDescription([])\n"),
    "read_outside": HEAD + ("def generate_launch_description():\n"
                            "    secret = open({secret!r}).read()\n"
                            "    return LaunchDescription([Node(package='turtlesim', executable='turtlesim_node', "
                            "name=secret)])\n"),
    "leftover": "import os\nimport time\n" + HEAD + ("def generate_launch_description():\n"
                                                     "    if os.fork() == 0:\n        time.sleep(60)\n"
                                                     "        os._exit(0)\n    return LaunchDescription([])\n"),
    "print_flood": HEAD + ("def generate_launch_description():\n    while True:\n        print('x' * 65536)\n"),
}


@pytest.fixture(scope="module")
def results(tmp_path_factory: pytest.TempPathFactory) -> dict[str, tuple[object, float]]:
    root = tmp_path_factory.mktemp("evil")
    package = root / "evil_pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML)
    target = root / "outside.txt"
    secret = tmp_path_factory.mktemp("grader_side") / "answers.txt"
    secret.write_text("the_answers")
    found: dict[str, tuple[object, float]] = {}
    for name, text in ATTACKS.items():
        path = package / "launch" / f"{name}.launch.py"
        path.write_text(text.replace("{target!r}", repr(str(target))).replace("{secret!r}", repr(str(secret))))
        start = time.monotonic()
        try:
            outcome: object = evaluate(path, read_workspace(root), [], limits=SHORT).result
        except Ros2LaunchError as exc:
            outcome = exc
        found[name] = (outcome, time.monotonic() - start)
    found["_target"] = (target, 0.0)
    return found


def _message(outcome: object) -> str:
    if isinstance(outcome, Ros2LaunchError):
        return str(outcome)
    assert isinstance(outcome, dict) and outcome["error"], outcome
    return outcome["error"]["message"]


@pytest.mark.slow
def test_endless_loop_is_stopped_in_bounded_time(results: dict) -> None:
    outcome, took = results["loop"]
    assert "did not finish" in _message(outcome) or "CPU" in _message(outcome)
    assert took < SHORT.wall_s + 5


@pytest.mark.slow
def test_self_include_is_a_finding(results: dict) -> None:
    assert "includes itself" in _message(results["self_include"][0])


@pytest.mark.slow
def test_ten_thousand_nodes_are_refused(results: dict) -> None:
    assert "more than 200 processes" in _message(results["many_nodes"][0])


@pytest.mark.slow
def test_absent_import_is_named(results: dict) -> None:
    assert "No module named 'com2009_secret_helpers'" in _message(results["absent_import"][0])


# Reading and writing outside the submission are stopped by the sandbox (bubblewrap or namespaces), as for nodes; with
# rlimits only the launch file runs as the grader's user, whose files it can reach (README, "Isolation").
needs_sandbox = pytest.mark.skipif(not confine.detect().namespaces, reason="neither bubblewrap nor user namespaces "
                                   "(unshare) are available here: launch files run with " + confine.detect().isolation)


@pytest.mark.slow
@needs_sandbox
def test_writing_outside_the_submission_fails_and_writes_nothing(results: dict) -> None:
    assert _message(results["write_outside"][0])
    assert not Path(results["_target"][0]).exists()


@pytest.mark.slow
@needs_sandbox
def test_reading_outside_the_submission_finds_nothing(results: dict) -> None:
    message = _message(results["read_outside"][0])
    assert "No such file or directory" in message or "Permission denied" in message
    assert "the_answers" not in message


@pytest.mark.slow
def test_endless_output_is_bounded(results: dict) -> None:
    outcome, took = results["print_flood"]
    assert "File too large" in _message(outcome)  # its output stops at the file-size limit
    assert took < SHORT.wall_s + 5
    assert len(_message(outcome)) < 10_000


@pytest.mark.slow
def test_a_process_left_behind_neither_delays_nor_outlives_the_evaluation(results: dict) -> None:
    outcome, took = results["leftover"]
    assert isinstance(outcome, dict) and outcome["error"] is None
    assert took < 5
    survivors = [pid for pid in os.listdir("/proc") if pid.isdigit() and _cmdline(pid).endswith("leftover.launch.py")]
    assert survivors == []


def _cmdline(pid: str) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace").strip()
    except OSError:
        return ""
