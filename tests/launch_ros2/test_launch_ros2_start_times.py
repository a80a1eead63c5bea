"""A launch file's TimerAction and OnProcessStart / OnProcessExit handlers become the nodes' start times in the run
(sim time, grader/runtime/start_order.py): the delay after the start, or the node they wait for and the delay after
its event; a node started on launch's shutdown is not run, as launch starts nothing once it shuts down."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from grader.launch.ros2_specs import ros2_node_specs
from grader.runtime.spec import Start
from grader.workspace import read_workspace

pytestmark = pytest.mark.slow  # one confined evaluation of the launch file, about 0.5 s

ROOT = Path(__file__).resolve().parents[2]
LAUNCH = '''
from launch import LaunchDescription
from launch.actions import RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessExit, OnProcessStart, OnShutdown
from launch_ros.actions import Node


def generate_launch_description():
    printer = Node(package="part2_navigation", executable="odom_subscriber", name="printer")
    mover = Node(package="part2_navigation", executable="move_square", name="mover")
    again = Node(package="part2_navigation", executable="odom_subscriber", name="again")
    last = Node(package="part2_navigation", executable="move_circle", name="last")
    return LaunchDescription([
        TimerAction(period=2.5, actions=[printer]),
        RegisterEventHandler(OnProcessStart(target_action=printer, on_start=[mover])),
        RegisterEventHandler(OnProcessExit(target_action=mover, on_exit=[TimerAction(period=1.0, actions=[again])])),
        RegisterEventHandler(OnShutdown(on_shutdown=[last])),
    ])
'''


@pytest.fixture(scope="module")
def evaluated(tmp_path_factory: pytest.TempPathFactory):
    folder = tmp_path_factory.mktemp("ws")
    package = folder / "part2_navigation"
    shutil.copytree(ROOT / "reference_solutions_ros2" / "part2_navigation", package)
    (package / "launch").mkdir()
    (package / "launch" / "timed.launch.py").write_text(LAUNCH)
    setup = (package / "setup.py").read_text()
    installed = "('share/' + package_name, ['package.xml']),"
    (package / "setup.py").write_text(setup.replace(installed, installed + "\n        ('share/' + package_name + "
                                                    "'/launch', ['launch/timed.launch.py']),"))
    workspace = read_workspace(folder)
    return ros2_node_specs(package / "launch" / "timed.launch.py", workspace, {}, None)


def test_timers_and_handlers_become_start_times(evaluated) -> None:
    specs, _, _ = evaluated
    assert [spec.script.name for spec in specs] == ["odom_subscriber.py", "move_square.py", "odom_subscriber.py"]
    assert [spec.start for spec in specs] == [
        Start(delay_s=2.5, said="2.5 s after the start (TimerAction)"),
        Start(delay_s=0.0, after=0, on="start", said="when odom_subscriber-1 starts"),
        Start(delay_s=1.0, after=1, on="exit", said="when move_square-2 exits"),
    ]


def test_a_node_started_on_shutdown_is_not_run_and_said_so(evaluated) -> None:
    _, findings, _ = evaluated
    assert any("move_circle starts when launch shuts down (OnShutdown); rosgrade does not run it" in f
               for f in findings), findings
