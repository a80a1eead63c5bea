"""turtlesim's ``mimic`` in a ROS 1 launch file (the ROS wiki's roslaunch tutorial, turtlemimic.launch): it runs the
grader's rospy mimic (grader/nodes/turtle_mimic.py) with the launch file's name, namespace and remaps, and a turtle
driven through it copies the velocities of the turtle it hears.

Noetic's turtlesim 0.10.2 tutorials/mimic.cpp publishes, for each turtlesim/Pose on ``input/pose``, a Twist with
linear.x = linear_velocity and angular.z = angular_velocity on ``output/cmd_vel``; its topics hang off
``ros::NodeHandle("input")`` and ``("output")``, whose namespaces roscpp remaps, which is why the tutorial remaps
``input`` and ``output`` rather than the topics. turtle.cpp takes a command at its next 16 ms update.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from grader.launch import find_packages, read_launch
from grader.launch.specs import node_specs
from grader.recording import Recording
from grader.rubric import GRADER_NODES
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

CASES = Path(__file__).resolve().parent / "mimic_ws" / "src" / "mimic_cases" / "launch"
UPDATE_S = 0.016  # turtle.cpp's update period: the follower is one update behind
LEADER = (1.0, 0.5)  # lead_turtle1.py's command: 1 m/s, 0.5 rad/s


def _specs(name: str) -> tuple[NodeSpec, ...]:
    path = CASES / name
    packages = find_packages(path.parents[2])
    specs, notes = node_specs(read_launch(path, {}, packages), packages)
    assert notes == []
    return specs


def test_a_launch_files_mimic_runs_the_graders_rospy_mimic_with_its_remaps() -> None:
    leader, mimic = _specs("mimic_root.launch")
    assert (leader.script.name, leader.provided) == ("lead_turtle1.py", False)
    assert (mimic.script, mimic.provided, mimic.flavour) == (GRADER_NODES / "turtle_mimic.py", True, "ros1")
    assert mimic.args == ("input:=turtle1", "output:=turtle2", "__name:=mimic")


def test_the_tutorials_remap_of_input_reaches_a_namespaced_turtlesim() -> None:
    (mimic,) = _specs("mimic_tutorial_ns.launch")
    assert mimic.script.name == "turtle_mimic.py" and mimic.ros_namespace is None
    assert mimic.args[:2] == ("input:=turtlesim1/turtle1", "output:=turtlesim2/turtle1")  # its own remaps first
    # the node's input/pose resolves to /turtlesim1/turtle1/pose, which the bridge leads to the world's turtle1
    assert "/turtlesim1/turtle1/pose:=/turtle1/pose" in mimic.args
    assert mimic.args[-1] == "__name:=mimic"


@pytest.fixture(scope="module")
def recording(tmp_path_factory: pytest.TempPathFactory) -> Recording:
    tmp = tmp_path_factory.mktemp("ros1_mimic")
    result = run(RunSpec(scenario=Scenario(robot="turtlesim", duration=4.0), nodes=_specs("mimic_root.launch")),
                 tmp / "run.mcap", tmp / "run.log")
    assert [(n.name, n.status) for n in result.nodes] == [("/leader", "stopped_at_end"), ("/mimic", "stopped_at_end")]
    return Recording.open(tmp / "run.mcap")


@pytest.mark.slow
def test_mimic_publishes_each_pose_it_hears_as_a_twist_of_its_velocities(recording: Recording) -> None:
    velocities = {t: (m.linear_velocity, m.angular_velocity) for t, m in recording.messages("/turtle1/pose")}
    # before turtle2 is spawned nothing listens on /turtle2/cmd_vel: those twists are recorded as lost
    sent = [*recording.messages("/rosgrade/lost/turtle2/cmd_vel"), *recording.messages("/turtle2/cmd_vel")]
    answered = [(t, (m.linear.x, m.angular.z)) for t, m in sent]
    assert len(answered) > 200 and all(velocities[t] == twist for t, twist in answered)
    first = answered[0][0]  # from its first pose on, one twist per pose (the last pose ends the run unanswered)
    assert [t for t, _ in answered] == [t for t in sorted(velocities) if first <= t < max(velocities)]
    assert answered[-1][1] == pytest.approx(LEADER)


@pytest.mark.slow
def test_turtle2_drives_as_turtle1_drives_one_update_behind(recording: Recording) -> None:
    paths = [np.array([(m.x, m.y, m.theta) for _, m in recording.messages(topic)])
             for topic in ("/turtle1/pose", "/turtle2/pose")]
    leader, follower = (float(np.hypot(*np.diff(p[:, :2], axis=0).T).sum()) for p in paths)
    assert leader > 3.0
    assert follower == pytest.approx(leader - LEADER[0] * UPDATE_S, abs=1e-4)
    assert paths[1][-1, 2] == pytest.approx(paths[0][-1, 2] - LEADER[1] * UPDATE_S, abs=1e-5)
    assert tuple(paths[1][0, :2]) == (2.0, 2.0)  # spawned where the leader asked
