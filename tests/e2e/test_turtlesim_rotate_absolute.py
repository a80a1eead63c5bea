"""turtle1's rotate_absolute as the grader's node serves it beside the world, against Jazzy's turtle.cpp semantics.

From ros/ros_tutorials rolling 1.8.2 (Jazzy's turtlesim), turtlesim/src/turtle.cpp: every goal and every cancel is
accepted (lines 101-111); a goal accepted while another runs aborts it with the warning "Rotation goal received before a
previous goal finished. Aborting previous goal" and takes the heading as its start (rotateAbsoluteAcceptCallback, lines
173-189); on each update, a cancelled goal ends CANCELED ("Rotation goal canceled") with the turtle stopped (lines
231-239), else ``delta`` = normalize(start heading - heading) and feedback ``remaining`` = normalize(theta - heading)
(lines 240-249), and within 0.02 rad the goal SUCCEEDS ("Rotation goal completed successfully") with the turtle stopped
(lines 251-259), otherwise it turns at 1 rad/s the short way (lines 260-264). A velocity command during a goal aborts
it (velocityCallback, lines 131-136): submissions_example/gia_ros2_rotate_stop_twist shows that one.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from grader.metrics.run import RunData
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

HERE = Path(__file__).resolve().parent
CLIENT = HERE / "turtlesim_ros2_nodes" / "rotate_goals_ros2.py"
SERVER = HERE.parents[1] / "grader" / "nodes" / "turtlesim_rotate_absolute.py"
LINE = re.compile(r"^(\w+): status (\d) delta (\S+) feedback (\d+) first (\S+) last (\S+)$")

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def goals(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("rotate_absolute")
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=8.0, command_types=["geometry_msgs/Twist"]),
                   nodes=(NodeSpec(script=CLIENT, flavour="ros2"), NodeSpec(script=SERVER, flavour="ros2")))
    result = run(spec, tmp / "run.mcap", tmp / "run.log")
    assert result.nodes[0].status == "exited", result.nodes[0].message
    recording = Recording.open(tmp / "run.mcap")
    printed = {m.group(1): [float(v) for v in m.groups()[1:]]
               for line in recording.output_lines() if line.stream == "stdout" and (m := LINE.match(line.text))}
    logged = [(line.t, line.msg) for line in recording.rosout()]
    return printed, logged, RunData.from_recording(recording)


def test_a_newer_goal_aborts_the_running_one(goals) -> None:
    printed, logged, _ = goals
    status, delta, _, first, last = printed["replaced"]
    assert status == 6 and first == 1.0 and delta == pytest.approx(-(first - last), abs=2e-3)
    assert "Rotation goal received before a previous goal finished. Aborting previous goal" in [m for _, m in logged]


def test_the_newer_goal_succeeds_within_0_02_rad(goals) -> None:
    printed, logged, _ = goals
    status, delta, n_feedback, first, last = printed["newer"]
    assert status == 4 and abs(last) < 0.02 and n_feedback > 10
    assert delta == pytest.approx(-(first - last), abs=2e-3)  # start - end = -(turned) = -(first - last remaining)
    assert "Rotation goal completed successfully" in [m for _, m in logged]


def test_a_cancelled_goal_ends_canceled_and_the_turtle_stops(goals) -> None:
    printed, logged, data = goals
    status, _, _, first, _ = printed["cancelled"]
    assert status == 5 and first > math.pi - 0.2  # 2.0 from -0.99: turned the short way, anticlockwise
    cancelled_at = next(t for t, m in logged if m == "Rotation goal canceled")
    path = data.trajectory("ground_truth").between(cancelled_at + 0.05)
    assert len(path) > 10 and float(path.yaw.max() - path.yaw.min()) == 0.0
