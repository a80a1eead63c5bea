"""turtlesim's own ROS 2 nodes as the grader ships them: turtle_teleop_key (keys on stdin: an arrow publishes a Twist,
a rotate key sends a rotate_absolute goal) and mimic (a turtle copying another's velocities).

From ros/ros_tutorials rolling 1.8.2 (Jazzy's turtlesim): teleop_turtle_key.cpp declares ``scale_angular`` and
``scale_linear`` 2.0 (lines 188-189), sets ±1 for the arrows (lines 226-241) and publishes the parameter times it on
linear.x or angular.z (lines 290-293); ``r`` sends a RotateAbsolute goal of 1.5708 (lines 250-252). mimic.cpp publishes
each input pose's linear_velocity and angular_velocity as the output Twist (poseCallback). turtle.cpp holds a command
1 s.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from grader.metrics.run import RunData
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

HERE = Path(__file__).resolve().parent
NODES = HERE.parents[1] / "grader" / "nodes"

pytestmark = pytest.mark.slow


def _run(tmp: Path, name: str, *nodes: NodeSpec) -> RunData:
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=4.0, command_types=["geometry_msgs/Twist"]),
                   nodes=nodes)
    run(spec, tmp / f"{name}.mcap", tmp / f"{name}.log")
    return RunData.from_recording(Recording.open(tmp / f"{name}.mcap"))


def _teleop(stdin: str) -> NodeSpec:
    return NodeSpec(script=NODES / "turtle_teleop_key_ros2.py", flavour="ros2", stdin=stdin)


@pytest.fixture(scope="module")
def tmp(tmp_path_factory):
    return tmp_path_factory.mktemp("turtlesim_ros2_nodes")


def test_an_up_arrow_drives_the_turtle_2_m_in_1_s(tmp) -> None:
    data = _run(tmp, "arrow", _teleop("\x1b[A"))
    path = data.trajectory("ground_truth")
    assert float(path.x[-1] - path.x[0]) in (pytest.approx(1.984), pytest.approx(2.016))  # 62 or 63 updates
    assert list(data.commands.linear[:, 0]) == [2.0]


def test_the_r_key_turns_the_turtle_to_1_5708_through_the_action(tmp) -> None:
    server = NodeSpec(script=NODES / "turtlesim_rotate_absolute.py", flavour="ros2")
    data = _run(tmp, "rotate", _teleop("r"), server)
    goals = [c for c in data.service_calls if c.service == "/turtle1/rotate_absolute/_action/send_goal"]
    assert len(goals) == 1 and goals[0].request["goal"].theta == pytest.approx(1.5708)
    assert abs(float(data.trajectory("ground_truth").yaw[-1]) - 1.5708) < 0.02


def test_mimic_drives_turtle2_as_turtle1_drives(tmp) -> None:
    mimic = NodeSpec(script=NODES / "turtle_mimic_ros2.py", flavour="ros2",
                     args=("--ros-args", "-r", "input/pose:=/turtle1/pose", "-r", "output/cmd_vel:=/turtle2/cmd_vel"))
    data = _run(tmp, "mimic", NodeSpec(script=HERE / "turtlesim_ros2_nodes" / "spawn_and_lead_ros2.py",
                                       flavour="ros2"), mimic)
    leader, follower = data.trajectory("ground_truth"), data.poses["/turtle2/pose"]
    travelled = [float(np.hypot(np.diff(p.x), np.diff(p.y)).sum()) for p in (leader, follower)]
    assert travelled[1] == pytest.approx(travelled[0], abs=0.02)  # one 16 ms update behind
    assert float(follower.yaw[-1]) == pytest.approx(float(leader.yaw[-1]), abs=0.01)
