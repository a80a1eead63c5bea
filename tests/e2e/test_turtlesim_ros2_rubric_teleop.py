"""A rubric's [[grader_nodes]] start turtlesim's own nodes as the run's ROS version has them: `turtle_teleop_key.py`
in an rclpy run is Jazzy's teleop (grader/nodes/turtle_teleop_key_ros2.py), its keys typed from the scenario's stdin,
with the rotate_absolute server its rotate keys need started beside it; a rospy run keeps Noetic's teleop. `mimic`
(turtle_mimic.py; turtle_mimic_ros2.py in an rclpy run) is started with the remaps the rubric gives, as the launch
tutorial's file does.

Jazzy's teleop_turtle_key.cpp (ros/ros_tutorials rolling 1.8.2, what Jazzy ships; the snapshot has no jazzy branch)
sends `r` as a RotateAbsolute goal of 1.5708 and `c` as -2.3562 (lines 250-268); turtle.cpp turns the turtle at 1 rad/s
the short way and ends the goal within 0.02 rad of theta (rotateAbsoluteAcceptCallback / update).
"""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from grader.grading import grade_task
from grader.metrics.run import RunData
from grader.provided_nodes import provided_specs, script_for
from grader.recording import Recording
from grader.rubric import GraderNode, Rubric
from grader.workspace import read_workspace

HERE = Path(__file__).resolve().parent
PROBE = {
    "id": "teleop_rotate_probe", "title": "teleop's rotate keys", "robot": "turtlesim",
    "nodes": [{"script": "pose_listener.py"}],
    "grader_nodes": [{"script": "turtle_teleop_key.py"}],
    "scenario_defaults": {"command_types": ["geometry_msgs/Twist"], "duration": 5.0},
    "scenarios": [{"name": "key_r", "stdin": "r", "params": {"theta": 1.5708}},
                  {"name": "key_c", "stdin": "c", "params": {"theta": -2.3562}}],
    "criteria": [{"id": "heading", "title": "turtle1 ends at the key's heading", "points": 1,
                  "metric": "rotate_absolute", "quantity": "heading_error_deg", "tolerance": {"bounds": [0.0, 1.2]}}],
}


def test_a_ros2_run_gets_jazzy_teleop_and_the_rotate_server_a_ros1_run_noetic_teleop(tmp_path) -> None:
    teleop = [GraderNode(script="turtle_teleop_key.py")]
    ros2 = provided_specs(teleop, "ros2", read_workspace(tmp_path))
    assert [(s.script.name, s.flavour, s.provided) for s in ros2] == [
        ("turtle_teleop_key_ros2.py", "ros2", True), ("turtlesim_rotate_absolute.py", "ros2", True)]
    ros1 = provided_specs(teleop, "ros1", read_workspace(tmp_path))
    assert [(s.script.name, s.flavour) for s in ros1] == [("turtle_teleop_key.py", "ros1")]
    assert script_for("turtle_mimic.py", "ros2") == "turtle_mimic_ros2.py"
    assert script_for("turtle_mimic.py", "ros1") == "turtle_mimic.py"
    assert script_for("number_game_server.py", "ros2") == "number_game_server.py"  # no variant: as named


def test_a_rubric_listing_the_rotate_server_gets_it_once(tmp_path) -> None:
    nodes = [GraderNode(script="turtlesim_rotate_absolute.py"), GraderNode(script="turtle_teleop_key.py")]
    names = [s.script.name for s in provided_specs(nodes, "ros2", read_workspace(tmp_path))]
    assert names == ["turtlesim_rotate_absolute.py", "turtle_teleop_key_ros2.py"]


@pytest.mark.slow
def test_ros2_teleop_rotate_keys_from_stdin_turn_the_turtle_to_their_absolute_angles(tmp_path) -> None:
    submission = tmp_path / "submission"
    submission.mkdir()
    shutil.copy(HERE / "turtlesim_ros2_nodes" / "pose_listener_ros2.py", submission / "pose_listener.py")
    report = grade_task(submission, Rubric.model_validate(PROBE), tmp_path / "out")
    assert report.status == "graded", report.message
    assert report.score == report.max_score, [c.feedback for c in report.criteria]
    goals = {}
    for path in report.recordings:
        data = RunData.from_recording(Recording.open(path))
        goals[Path(path).stem] = [c.request["goal"].theta for c in data.service_calls
                                  if c.service == "/turtle1/rotate_absolute/_action/send_goal"]
        assert data.trajectory("ground_truth").yaw[0] == 0.0  # it started facing east and turned
    assert goals == {"key_r": [pytest.approx(1.5708)], "key_c": [pytest.approx(-2.3562)]}


MIMIC = {
    "id": "mimic_probe", "title": "mimic from a rubric", "robot": "turtlesim",
    "nodes": [{"script": "leader.py"}],
    "grader_nodes": [{"script": "turtle_mimic.py", "args": ["--ros-args", "-r", "input/pose:=/turtle1/pose",
                                                            "-r", "output/cmd_vel:=/turtle2/cmd_vel"]}],
    "scenario_defaults": {"command_types": ["geometry_msgs/Twist"], "duration": 3.0},
    "scenarios": [{"name": "nominal"}],
    "criteria": [{"id": "no_wall_hit", "title": "no wall hit", "points": 1, "metric": "wall_hits",
                  "quantity": "n_wall_hits", "tolerance": {"bounds": [0.0, 0.0]}}],
}


@pytest.mark.slow
def test_mimic_from_a_rubric_drives_turtle2_as_turtle1_drives(tmp_path) -> None:
    submission = tmp_path / "submission"
    submission.mkdir()
    shutil.copy(HERE / "turtlesim_ros2_nodes" / "spawn_and_lead_ros2.py", submission / "leader.py")
    report = grade_task(submission, Rubric.model_validate(MIMIC), tmp_path / "out")
    assert report.status == "graded", report.message
    data = RunData.from_recording(Recording.open(report.recordings[0]))
    leader, follower = data.trajectory("ground_truth"), data.poses["/turtle2/pose"]
    travelled = [float(np.hypot(np.diff(p.x), np.diff(p.y)).sum()) for p in (leader, follower)]
    assert travelled[0] > 1.0 and travelled[1] == pytest.approx(travelled[0], abs=0.05)
