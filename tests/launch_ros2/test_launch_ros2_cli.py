"""`rosgrade launch` on ROS 2 launch files: PKG FILE finds installed files only, --nodes, --show-args as
`ros2 launch --show-args` prints them, --json, and errors with the real text."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from grader.cli import main

WS = Path(__file__).resolve().parent / "cases" / "ws"
LAUNCH = WS / "course_pkg" / "launch"

pytestmark = pytest.mark.slow  # each command evaluates the launch file in the sandbox (~0.3 s)


def test_package_and_file_with_an_argument(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["launch", "--workspace", str(WS), "course_pkg", "move_distance.launch.py", "distance:=2",
                 "--nodes"]) == 0
    assert capsys.readouterr().out == "/mover  (course_pkg mover)\n"


def test_nodes_say_what_starts_them(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["launch", str(LAUNCH / "example_event_handlers.launch.py"), "--nodes"]) == 0
    assert capsys.readouterr().out == (
        "/turtlesim1/sim  (turtlesim turtlesim_node) (simulated by rosgrade)\n"
        "ros2 service call /turtlesim1/spawn turtlesim/srv/Spawn {x: 2, y: 2, theta: 0.2}  [when turtlesim_node-1 "
        "starts]\n"
        "ros2 param set /turtlesim1/sim background_r 120  [when ros2-2 exits]\n")


def test_show_args_prints_as_ros2_launch(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["launch", str(LAUNCH / "move_distance.launch.py"), "--show-args"]) == 0
    assert capsys.readouterr().out == (
        "Arguments (pass arguments as '<name>:=<value>'):\n\n"
        "    'distance':\n        How far to drive (m)\n        (default: '1.0')\n\n"
        "    'speed':\n        no description given\n        (default: '0.15')\n")


def test_json_holds_argv_and_parameter_files(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["launch", str(LAUNCH / "waypoints.launch.xml"), "tolerance:=0.1", "--json"]) == 0
    processes = json.loads(capsys.readouterr().out)["processes"]
    assert [p["name"] for p in processes] == ["turtlesim_node-1", "waypoints-2"]
    waypoints = processes[1]
    assert waypoints["args"][:3] == ["--ros-args", "-r", "__node:=waypoints"]
    assert waypoints["params_files"][0]["content"] == "/**:\n  ros__parameters:\n    tolerance: 0.1\n"


def test_real_error_text_with_the_line(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["launch", str(LAUNCH / "error_python.launch.py"), "--nodes"]) == 2
    err = capsys.readouterr().err
    assert "[ERROR] [launch]: Caught exception in launch (see debug for traceback): Caught multiple exceptions" in err
    assert "NameError: name 'undefined_nodes' is not defined" in err
    assert "error_python.launch.py:7" in err


def test_undeclared_argument_is_noted(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["launch", str(LAUNCH / "task1.launch.py"), "speed:=3", "--nodes"]) == 0
    assert "argument speed:=3 is not declared by the launch file" in capsys.readouterr().err


def test_a_launch_file_cmake_does_not_install_is_not_found(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    package = tmp_path / "cm_pkg"
    (package / "launch").mkdir(parents=True)
    (package / "launch" / "go.launch.py").write_text((LAUNCH / "task1.launch.py").read_text())
    (package / "package.xml").write_text(
        '<?xml version="1.0"?><package format="3"><name>cm_pkg</name><version>0.0.0</version><description>x'
        '</description><maintainer email="a@b.c">a</maintainer><license>MIT</license><buildtool_depend>ament_cmake'
        '</buildtool_depend><export><build_type>ament_cmake</build_type></export></package>')
    (package / "CMakeLists.txt").write_text("cmake_minimum_required(VERSION 3.8)\nproject(cm_pkg)\n"
                                            "find_package(ament_cmake REQUIRED)\nament_package()\n")
    assert main(["launch", "--workspace", str(tmp_path), "cm_pkg", "go.launch.py", "--nodes"]) == 2
    err = capsys.readouterr().err
    assert "file 'go.launch.py' was not found in the share directory of package 'cm_pkg'" in err
    assert "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})" in err
    (package / "CMakeLists.txt").write_text("cmake_minimum_required(VERSION 3.8)\nproject(cm_pkg)\n"
                                            "find_package(ament_cmake REQUIRED)\ninstall(DIRECTORY launch DESTINATION "
                                            "share/${PROJECT_NAME})\nament_package()\n")
    assert main(["launch", "--workspace", str(tmp_path), "cm_pkg", "go.launch.py", "--nodes"]) == 2
    err = capsys.readouterr().err
    assert "\"package 'course_pkg' not found" in err
    assert "No package.xml in the submission says <name>course_pkg</name> (its packages: cm_pkg)" in err


def test_an_executable_not_installed_names_those_that_are(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["launch", str(LAUNCH / "error_bad_executable.launch.py"), "--nodes"]) == 2
    err = capsys.readouterr().err
    assert "executable 'move_robot.py' not found on the libexec directory" in err
    assert "The build of course_pkg installs: beacon_search, figure_of_eight, follower" in err


def test_roslaunch_xml_still_needs_nodes_or_dump_params(capsys: pytest.CaptureFixture[str]) -> None:
    ros1 = Path(__file__).resolve().parents[2] / "submissions_example" / "quinn_launch_remap" / "catkin_ws" / "src" \
        / "hello_world" / "launch" / "move_turtlebot.launch"
    assert main(["launch", str(ros1)]) == 2
    assert "--nodes or --dump-params" in capsys.readouterr().err


def test_an_external_node_that_needs_xacro_is_listed_not_evaluated(tmp_path: Path,
                                                                  capsys: pytest.CaptureFixture[str]) -> None:
    shutil.copytree(WS / "course_pkg", tmp_path / "course_pkg")
    launch = tmp_path / "course_pkg" / "launch" / "with_description.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\nfrom launch.substitutions import Command\n"
        "from launch_ros.actions import Node\nfrom launch_ros.parameter_descriptions import ParameterValue\n\n\n"
        "def generate_launch_description():\n"
        "    description = ParameterValue(Command(['xacro ', '/opt/ros/jazzy/share/turtlebot3_description/urdf/"
        "turtlebot3_waffle.urdf']), value_type=str)\n"
        "    return LaunchDescription([\n"
        "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
        "             parameters=[{'robot_description': description}]),\n"
        "        Node(package='course_pkg', executable='mover', name='mover'),\n"
        "    ])\n")
    assert main(["launch", str(launch), "--nodes"]) == 0
    assert capsys.readouterr().out == (
        "robot_state_publisher (the name its code gives it)  (robot_state_publisher robot_state_publisher) "
        "(external: not run by rosgrade)\n"
        "/mover  (course_pkg mover)\n")


def test_a_simulator_world_include_starts_nothing_and_is_noted(tmp_path: Path,
                                                               capsys: pytest.CaptureFixture[str]) -> None:
    shutil.copytree(WS / "course_pkg", tmp_path / "course_pkg")
    launch = tmp_path / "course_pkg" / "launch" / "sim_and_node.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\nfrom launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "from launch.substitutions import PathJoinSubstitution\nfrom launch_ros.actions import Node\n"
        "from launch_ros.substitutions import FindPackageShare\n\n\n"
        "def generate_launch_description():\n"
        "    world = PathJoinSubstitution([FindPackageShare('turtlebot3_gazebo'), 'launch', "
        "'turtlebot3_world.launch.py'])\n"
        "    return LaunchDescription([\n"
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource(world), launch_arguments={'x_pose': '-2.0'}"
        ".items()),\n"
        "        Node(package='course_pkg', executable='mover', name='mover'),\n"
        "    ])\n")
    assert main(["launch", str(launch), "--nodes"]) == 0
    captured = capsys.readouterr()
    assert captured.out == "/mover  (course_pkg mover)\n"
    assert "includes turtlebot3_gazebo's turtlebot3_world.launch.py x_pose:=-2.0: that package is not the " \
           "submission's; rosgrade provides the simulation itself" in captured.err


def test_json_is_the_same_every_time(capsys: pytest.CaptureFixture[str]) -> None:
    outputs = []
    for _ in range(2):
        assert main(["launch", str(LAUNCH / "params_types.launch.py"), "--json"]) == 0
        outputs.append(capsys.readouterr().out)
    assert outputs[0] == outputs[1]
    assert "launch_params_1" in outputs[0]


def test_command_line_mistakes_are_one_clear_line(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    assert main(["launch", "--workspace", str(tmp_path / "none"), "course_pkg", "task1.launch.py", "--nodes"]) == 2
    assert capsys.readouterr().err == f"rosgrade: error: {tmp_path / 'none'} does not exist\n"
    assert main(["launch", str(LAUNCH / "task1.launch.py"), "--dump-params"]) == 2
    assert "for a ROS 2 launch file use --json" in capsys.readouterr().err


def test_the_launch_file_sees_a_course_machines_environment(tmp_path: Path,
                                                            capsys: pytest.CaptureFixture[str]) -> None:
    shutil.copytree(WS / "course_pkg", tmp_path / "course_pkg")
    launch = tmp_path / "course_pkg" / "launch" / "model.launch.py"
    launch.write_text("import os\nfrom launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
                      "def generate_launch_description():\n"
                      "    return LaunchDescription([Node(package='course_pkg', executable='mover', "
                      "name=os.environ['TURTLEBOT3_MODEL'] + '_' + os.environ['ROS_DISTRO'])])\n")
    assert main(["launch", str(launch), "--nodes"]) == 0
    assert capsys.readouterr().out == "/waffle_jazzy  (course_pkg mover)\n"
