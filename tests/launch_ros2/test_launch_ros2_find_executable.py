"""FindExecutable / $(find-exec) give the path `which` gives on a ROS 2 Jazzy machine, so the substitutions tutorial's
`[FindExecutable(name='ros2'), ' service call ', ...]` reads as real launch reads it there."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.launch.ros2_eval import evaluate
from grader.workspace import read_workspace

pytestmark = pytest.mark.slow  # one confined evaluation, about 0.5 s

LAUNCH = '''
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch.substitutions import FindExecutable


def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=[[FindExecutable(name='ros2'), ' service call ', '/spawn ', 'turtlesim/srv/Spawn ',
                             '"{x: 2, y: 2}"']], shell=True),
        ExecuteProcess(cmd=[FindExecutable(name='python3'), '-c', 'pass']),
        ExecuteProcess(cmd=[FindExecutable(name='bad/name')]),
    ])
'''


def test_ros2_and_python3_are_where_a_jazzy_machine_has_them_and_a_path_is_refused(tmp_path: Path) -> None:
    (tmp_path / "t.launch.py").write_text(LAUNCH)
    result = evaluate(tmp_path / "t.launch.py", read_workspace(tmp_path), []).result
    assert "executable 'bad/name' not found on the PATH" in result["error"]["message"]
    (tmp_path / "t.launch.py").write_text(LAUNCH.replace("        ExecuteProcess(cmd=[FindExecutable(name='bad/name')]),\n", ""))
    result = evaluate(tmp_path / "t.launch.py", read_workspace(tmp_path), []).result
    assert [p["cmd"][0] for p in result["processes"]] == [
        '/opt/ros/jazzy/bin/ros2 service call /spawn turtlesim/srv/Spawn "{x: 2, y: 2}"', "/usr/bin/python3"]
