"""turtlesim's own nodes in a ROS 2 launch file: turtle_teleop_key and mimic run as the grader's shipped ROS 2 nodes
(the teleop with the rotate_absolute server) with the launch description's name, namespace, remappings and stdin; a
turtlesim_node in a namespace is bridged to the one world, so a node beside it reaches the turtle and a node elsewhere
does not, and the launch file's ros2 command lines reach it; a second turtlesim_node is a window of its own."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from grader.cli import main
from grader.launch import LaunchError
from grader.launch.ros2_specs import ros2_node_specs
from grader.provided_nodes import GRADER_NODES
from grader.workspace import read_workspace

pytestmark = pytest.mark.slow  # each case evaluates a launch file confined, about 0.5 s

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = ROOT / "reference_solutions_turtlesim_ros2" / "lab2_turtlesim"
HEADER = """
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
"""


def _specs(tmp_path: Path, nodes: str, args: dict[str, str] | None = None):
    package = tmp_path / "lab2_turtlesim"
    shutil.copytree(REFERENCE, package)
    (package / "launch" / "case.launch.py").write_text(HEADER + nodes + "\n    ])\n")
    return ros2_node_specs(package / "launch" / "case.launch.py", read_workspace(tmp_path), args or {}, "\x1b[A")


def _remaps(args: tuple[str, ...]) -> dict[str, str]:
    rules = [args[i + 1] for i in range(len(args) - 1) if args[i] == "-r" and not args[i + 1].startswith("__")]
    found: dict[str, str] = {}
    for rule in rules:  # rcl applies the first rule whose name matches
        source, _, target = rule.partition(":=")
        found.setdefault(source, target)
    return found


def test_the_reference_teleop_runs_as_the_graders_ros2_teleop_with_its_rotate_server(tmp_path: Path) -> None:
    launch = REFERENCE / "launch" / "teleopturtlesim4.launch.py"
    specs, findings, _ = ros2_node_specs(launch, read_workspace(REFERENCE), {"teleop": "1"}, "\x1b[A")
    assert [(s.script, s.provided) for s in specs] == [
        (GRADER_NODES / "turtle_teleop_key_ros2.py", True), (GRADER_NODES / "turtlesim_rotate_absolute.py", True)]
    teleop = specs[0]
    assert teleop.args == ("--ros-args", "-r", "__node:=teleop_key")
    assert teleop.stdin == "\x1b[A" and teleop.output == "screen" and teleop.flavour == "ros2"
    assert findings == []


def test_teleop_0_runs_the_students_pubvel_and_no_grader_node(tmp_path: Path) -> None:
    launch = REFERENCE / "launch" / "teleopturtlesim4.launch.py"
    specs, _, _ = ros2_node_specs(launch, read_workspace(REFERENCE), {"teleop": "0"}, None)
    assert [(s.script.name, s.provided) for s in specs] == [("pubvel.py", False)]


def test_mimic_gets_the_launch_tutorials_remappings_and_no_rotate_server(tmp_path: Path) -> None:
    specs, _, _ = _specs(tmp_path, """
        Node(package='turtlesim', executable='turtlesim_node', name='sim'),
        Node(package='turtlesim', executable='mimic', name='mimic',
             remappings=[('/input/pose', '/turtle1/pose'), ('/output/cmd_vel', '/turtle2/cmd_vel')]),
        Node(package='lab2_turtlesim', executable='pubvel'),""")
    assert [(s.script.name, s.provided) for s in specs] == [("turtle_mimic_ros2.py", True), ("pubvel.py", False)]
    assert specs[0].args == ("--ros-args", "-r", "__node:=mimic", "-r", "/input/pose:=/turtle1/pose",
                             "-r", "/output/cmd_vel:=/turtle2/cmd_vel")


def test_a_namespaced_turtlesim_is_reached_from_its_namespace_and_not_from_the_root(tmp_path: Path) -> None:
    specs, findings, _ = _specs(tmp_path, """
        Node(package='turtlesim', namespace='turtlesim1', executable='turtlesim_node', name='sim'),
        Node(package='turtlesim', namespace='turtlesim1', executable='turtle_teleop_key', name='teleop'),
        Node(package='turtlesim', executable='mimic', name='mimic',
             remappings=[('/input/pose', '/turtlesim1/turtle1/pose'), ('/output/cmd_vel', 'turtle1/cmd_vel')]),""")
    teleop, mimic, server = specs
    assert server.script.name == "turtlesim_rotate_absolute.py" and server.args == ()
    teleop_rules = _remaps(teleop.args)
    assert teleop_rules["/turtlesim1/turtle1/cmd_vel"] == "/turtle1/cmd_vel"
    assert teleop_rules["/turtlesim1/turtle1/rotate_absolute/_action/send_goal"] == \
        "/turtle1/rotate_absolute/_action/send_goal"
    # mimic's own rules come first, their targets led to the world; the root's turtle1/cmd_vel reaches no turtle
    mimic_rules = _remaps(mimic.args)
    assert mimic_rules["/input/pose"] == "/turtle1/pose"
    assert mimic_rules["/output/cmd_vel"] == "/no_turtlesim_here/turtle1/cmd_vel"
    assert findings == ["case.launch.py starts turtlesim_node as /turtlesim1/sim, so its turtle uses "
                        "/turtlesim1/turtle1/cmd_vel (recorded as /turtle1/cmd_vel), /turtlesim1/turtle1/pose "
                        "(recorded as /turtle1/pose), as with ros2 launch; turtlesim's usual names reach no turtle."]


MIMIC_TUTORIAL = """
        Node(package='turtlesim', namespace='turtlesim1', executable='turtlesim_node', name='sim'),
        Node(package='turtlesim', namespace='turtlesim2', executable='turtlesim_node', name='sim',
             parameters=[{'background_g': 20}]),
        Node(package='turtlesim', executable='mimic', name='mimic',
             remappings=[('/input/pose', '/turtlesim1/turtle1/pose'),
                         ('/output/cmd_vel', '/turtlesim2/turtle1/cmd_vel')]),"""


def test_the_launch_tutorials_two_turtlesims_are_two_windows(tmp_path: Path) -> None:
    specs, findings, acts = _specs(tmp_path, MIMIC_TUTORIAL)
    assert [(w.node, w.params) for w in acts.turtlesim_windows] == [("/turtlesim2/sim", {"background_g": 20})]
    mimic_rules = _remaps(specs[0].args)
    # the first window is bridged to turtlesim's own names; the second keeps the names it was launched with
    assert mimic_rules["/input/pose"] == "/turtle1/pose"
    assert mimic_rules["/output/cmd_vel"] == "/turtlesim2/turtle1/cmd_vel"
    assert findings[-1] == ("case.launch.py starts a second turtlesim window, /turtlesim2/sim: its turtles are "
                            "recorded under its names (/turtlesim2/turtle1/pose), and the task is graded on the first "
                            "window's turtle.")


def test_the_window_in_the_root_namespace_is_the_first(tmp_path: Path) -> None:
    _, findings, acts = _specs(tmp_path, """
        Node(package='turtlesim', namespace='other', executable='turtlesim_node', name='sim'),
        Node(package='turtlesim', executable='turtlesim_node'),
        Node(package='lab2_turtlesim', executable='pubvel'),""")
    assert [w.node for w in acts.turtlesim_windows] == ["/other/sim"]
    assert len(findings) == 1  # no bridge: the first window has turtlesim's own names


@pytest.mark.parametrize("nodes, said", [
    ("""
        Node(package='turtlesim', executable='turtlesim_node'),
        Node(package='turtlesim', executable='turtlesim_node', name='sim2'),""", "share its topics and services"),
    ("""
        Node(package='turtlesim', namespace='a', executable='turtlesim_node', name='sim'),
        Node(package='turtlesim', namespace='a', executable='turtlesim_node', name='sim'),""", "share its topics"),
    ("""
        Node(package='turtlesim', executable='turtlesim_node'),
        Node(package='turtlesim', namespace='b', executable='turtlesim_node', name='sim',
             remappings=[('turtle1/cmd_vel', '/x')]),""", "remap the nodes that talk to it instead"),
    ("""
        Node(package='turtlesim', executable='turtlesim_node'),
        Node(package='turtlesim', namespace='2nd', executable='turtlesim_node', name='sim'),""",
     "Invalid namespace: namespace must not have a token that starts with a number"),
])
def test_windows_rosgrade_cannot_tell_apart_are_refused_with_what_to_change(tmp_path: Path, nodes: str,
                                                                            said: str) -> None:
    with pytest.raises(LaunchError, match=said):
        _specs(tmp_path, nodes)


def test_a_turtlesim_node_rosgrade_does_not_ship_is_still_said_not_to_run(tmp_path: Path) -> None:
    specs, findings, _ = _specs(tmp_path, """
        Node(package='turtlesim', executable='turtlesim_node'),
        Node(package='turtlesim', executable='draw_square'),
        Node(package='lab2_turtlesim', executable='pubvel'),""")
    assert [s.script.name for s in specs] == ["pubvel.py"]
    assert findings == ["case.launch.py starts turtlesim draw_square, which rosgrade does not run (not part of the "
                        "graded simulation)."]


def test_rosgrade_launch_nodes_says_which_turtlesim_nodes_run(capsys: pytest.CaptureFixture[str]) -> None:
    tutorial = Path(__file__).resolve().parent / "cases" / "ws" / "course_pkg" / "launch" / "turtlesim_mimic.launch.py"
    assert main(["launch", str(tutorial), "--nodes"]) == 0
    assert capsys.readouterr().out == (
        "/turtlesim1/sim  (turtlesim turtlesim_node) (simulated by rosgrade)\n"
        "/turtlesim2/sim  (turtlesim turtlesim_node) (simulated by rosgrade: another turtlesim window, under its "
        "own names)\n"
        "/mimic  (turtlesim mimic) (run by rosgrade as turtlesim's own node)\n")


def test_the_teleops_parameters_are_its_own_not_the_worlds(tmp_path: Path) -> None:
    specs, _, acts = _specs(tmp_path, """
        Node(package='turtlesim', executable='turtlesim_node', parameters=[{'background_r': 10}]),
        Node(package='turtlesim', executable='turtle_teleop_key', parameters=[{'scale_linear': 1.0}]),""")
    assert acts.world_params == {"background_r": 10}
    teleop = specs[0]
    assert teleop.script.name == "turtle_teleop_key_ros2.py"
    assert [content for _, content in teleop.files] == [b"/**:\n  ros__parameters:\n    scale_linear: 1.0\n"]


def test_the_launch_files_ros2_commands_reach_a_namespaced_turtlesim(tmp_path: Path) -> None:
    _, _, acts = _specs(tmp_path, """
        Node(package='turtlesim', namespace='turtlesim1', executable='turtlesim_node', name='sim'),
        Node(package='lab2_turtlesim', executable='pubvel', namespace='turtlesim1'),
        ExecuteProcess(cmd=['ros2 service call /turtlesim1/spawn turtlesim/srv/Spawn "{x: 2, y: 2, name: t2}"'],
                       shell=True),
        ExecuteProcess(cmd=['ros2', 'param', 'set', '/turtlesim1/sim', 'background_r', '120']),
        ExecuteProcess(cmd=['ros2', 'topic', 'pub', '-t', '1', '/turtlesim1/turtle1/cmd_vel',
                            'geometry_msgs/msg/Twist', '{linear: {x: 1.0}}']),
        ExecuteProcess(cmd=['ros2', 'action', 'send_goal', '/turtlesim1/turtle1/rotate_absolute',
                            'turtlesim/action/RotateAbsolute', '{theta: 1.0}']),
        ExecuteProcess(cmd=['ros2', 'service', 'call', '/other/spawn', 'turtlesim/srv/Spawn', '{name: t3}']),""")
    assert [c.service for c in acts.service_calls] == ["/spawn", "/other/spawn"]
    assert [(p.node, p.name, p.value) for p in acts.param_sets] == [("/turtlesim", "background_r", 120)]
    assert [p.topic for p in acts.publications] == ["/turtle1/cmd_vel"]
    assert [g.action for g in acts.action_goals] == ["/turtle1/rotate_absolute"]
