"""The grader as an actionlib client: a rospy run's scenario action_goals go out on <ns>/goal as actionlib's client
sends them (id and stamps as real actionlib's ActionClient makes them), once the server's goal subscriber is connected,
and cancel_at sends the goal's GoalID on <ns>/cancel; the tutorial's SimpleActionServer answers on its topics."""
from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from grader.interfaces import run_interfaces
from grader.metrics.action_record import ROS1_REJECTED, ROS1_STATUS
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.scenario_actionlib import goal_id_text
from grader.runtime.session import run
from grader.workspace import read_workspace
from sim import Scenario

PACKAGE = Path(__file__).resolve().parents[2] / "reference_solutions_ros1_actionlib" / "actionlib_tutorials"
FIBONACCI = "actionlib_tutorials/action/Fibonacci"
# The ids real actionlib's ActionClient gives goals (GoalManager._generate_id, which uses no state of its own).
REAL_IDS = """
import rospy, rospy.names, rospy.rostime as clock
from actionlib.action_client import GoalManager
clock.set_rostime_initialized(True)
rospy.names._set_caller_id("/rosgrade")
for secs, nsecs in ((2, 110000000), (3, 50000000), (12, 5), (7, 999999999)):
    clock._set_rostime(rospy.Time(secs, nsecs))
    print(GoalManager._generate_id(None).id)
"""


@pytest.fixture(scope="module")
def recording(tmp_path_factory) -> Recording:
    folder = tmp_path_factory.mktemp("actionlib_goals")
    goals = [{"t": 0.0, "action": "/fibonacci", "type": FIBONACCI, "goal": {"order": 5}},
             {"t": 1.0, "action": "/fibonacci", "type": FIBONACCI, "goal": {"order": 20}, "cancel_at": 1.5}]
    spec = RunSpec(scenario=Scenario(duration=3.0, action_goals=goals),
                   nodes=(NodeSpec(script=PACKAGE / "scripts" / "fibonacci_server.py"),),
                   interfaces=run_interfaces(read_workspace(PACKAGE), "ros1"))
    run(spec, folder / "run.mcap", folder / "run.log")
    return Recording.open(folder / "run.mcap")


@pytest.mark.slow
def test_goals_and_cancel_go_out_on_actionlibs_topics_and_the_server_answers(recording) -> None:
    sent = [(topic, t, message) for topic, t, message in recording.messages_on(
        {"/fibonacci/goal", "/fibonacci/cancel", "/fibonacci/result"})]
    # the goal waits for the server's goal subscriber (registered at 2.06 s, connected 50 ms later: looked at every
    # 10 ms); each goal's publisher is made at its time, so the second goes out after its own 50 ms connect delay
    assert [(topic, t) for topic, t, _ in sent] == [("/fibonacci/goal", 2_110_000_000),
                                                    ("/fibonacci/result", 2_510_000_000),
                                                    ("/fibonacci/goal", 3_050_000_000),
                                                    ("/fibonacci/cancel", 3_500_000_000),
                                                    ("/fibonacci/result", 3_550_000_000)]
    first, second = sent[0][2], sent[2][2]
    assert (first.goal_id.id, first.goal_id.stamp.sec, first.goal_id.stamp.nanosec, first.header.stamp.nanosec,
            first.goal.order) == ("/rosgrade-1-2.110", 2, 110_000_000, 110_000_000, 5)
    assert (sent[3][2].id, sent[3][2].stamp.sec, sent[3][2].stamp.nanosec) == (second.goal_id.id, 0, 0)
    # SUCCEEDED (3) for the first, PREEMPTED (2) for the cancelled one
    assert [(m.status.goal_id.id, m.status.status) for topic, _, m in sent if topic.endswith("result")] == [
        ("/rosgrade-1-2.110", 3), ("/rosgrade-2-3.050", 2)]
    callers = {(i.topic, i.callerid, i.origin) for i in recording.topics() if i.topic.startswith("/fibonacci/")
               and i.callerid == "/rosgrade"}
    assert callers == {("/fibonacci/goal", "/rosgrade", "grader"), ("/fibonacci/cancel", "/rosgrade", "grader")}


@pytest.mark.slow
def test_goal_ids_are_those_real_actionlib_generates() -> None:
    real = subprocess.run(["/usr/bin/python3", "-c", REAL_IDS], capture_output=True, text=True, timeout=60)
    if real.returncode != 0 and "No module named" in real.stderr:
        pytest.skip(f"Debian's python3-actionlib is not installed: {real.stderr.strip()[-200:]}")
    assert real.stdout.split() == [goal_id_text(1, 2_110_000_000), goal_id_text(2, 3_050_000_000),
                                   goal_id_text(3, 12_000_000_005), goal_id_text(4, 7_999_999_999)]


REAL_STATUSES = """
from actionlib_msgs.msg import GoalStatus
for name in ("PENDING", "ACTIVE", "PREEMPTED", "SUCCEEDED", "ABORTED", "REJECTED", "PREEMPTING", "RECALLING",
             "RECALLED", "LOST"):
    print(name, getattr(GoalStatus, name))
"""
# action_msgs/msg/GoalStatus by name, for each actionlib status by name (REJECTED: a goal not accepted)
AS_ROS2 = {"PENDING": 1, "ACTIVE": 2, "PREEMPTED": 5, "SUCCEEDED": 4, "ABORTED": 6, "PREEMPTING": 3, "RECALLING": 3,
           "RECALLED": 5, "LOST": 0}


@pytest.mark.slow
def test_actionlib_statuses_read_as_their_ros2_twins_by_real_actionlib_msgs_numbers() -> None:
    real = subprocess.run(["/usr/bin/python3", "-c", REAL_STATUSES], capture_output=True, text=True, timeout=60)
    if real.returncode != 0 and "No module named" in real.stderr:
        pytest.skip(f"Debian's python3-actionlib-msgs is not installed: {real.stderr.strip()[-200:]}")
    numbers = {name: int(number) for name, number in (line.split() for line in real.stdout.splitlines())}
    assert numbers["REJECTED"] == ROS1_REJECTED
    assert {numbers[name]: ros2 for name, ros2 in AS_ROS2.items()} == ROS1_STATUS
