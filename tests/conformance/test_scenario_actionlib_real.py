"""Scenario action goals to a rospy server against Debian's real actionlib 1.14 client: a SimpleActionClient named
/rosgrade sends one goal and then a second it cancels, to a server that prints what arrives on the action's goal and
cancel topics (the id's form and count, its stamps, the cancel's id and stamp); rosgrade's goals to the same server
must arrive the same."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from real_ros import NOT_INSTALLED, REAL_PYTHON, RealRos, real_ros_available  # noqa: E402

from grader.recording import Recording  # noqa: E402
from grader.runtime import NodeSpec, RunSpec  # noqa: E402
from grader.runtime.session import run  # noqa: E402
from sim import Scenario  # noqa: E402

pytestmark = pytest.mark.slow

SERVER = Path(__file__).resolve().parents[1] / "runtime" / "nodes" / "topics" / "actionlib_count_server.py"
# The real client: actionlib's SimpleActionClient in a node named rosgrade, as the scenario's goals are sent.
CLIENT = """
import rospy, actionlib
from actionlib.msg import TestAction, TestGoal
rospy.init_node("rosgrade")
client = actionlib.SimpleActionClient("/count", TestAction)
client.wait_for_server()
client.send_goal(TestGoal(3))
client.wait_for_result()
client.send_goal(TestGoal(30))
rospy.sleep(0.5)
client.cancel_goal()
client.wait_for_result()
"""
EXPECTED = ["goal /rosgrade count 1 decimals 3 id time is its stamp True header stamp is its stamp True goal 3",
            "goal /rosgrade count 2 decimals 3 id time is its stamp True header stamp is its stamp True goal 30",
            "cancel of goal 2 stamp zero True"]


def test_real_actionlib_clients_goals_arrive_as_described() -> None:
    if not real_ros_available():
        pytest.skip(NOT_INSTALLED)
    with RealRos() as ros:
        client = subprocess.Popen([REAL_PYTHON, "-c", CLIENT], env=ros.env(), start_new_session=True,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        try:
            result = ros.run_probe(SERVER, duration=6.0)
        finally:
            client.kill()
            client.wait(5)
    assert result.stdout.splitlines() == EXPECTED, result.stderr


def test_rosgrade_goals_arrive_as_real_actionlibs_do(tmp_path) -> None:
    goals = [{"t": 0.5, "action": "/count", "type": "actionlib/action/Test", "goal": {"goal": 3}},
             {"t": 1.5, "action": "/count", "type": "actionlib/action/Test", "goal": {"goal": 30}, "cancel_at": 2.0}]
    run(RunSpec(scenario=Scenario(duration=4.0, action_goals=goals), nodes=(NodeSpec(script=SERVER),)),
        tmp_path / "r.mcap", tmp_path / "r.log")
    printed = [line.text for line in Recording.open(tmp_path / "r.mcap").output_lines() if line.stream == "stdout"]
    assert printed == EXPECTED
