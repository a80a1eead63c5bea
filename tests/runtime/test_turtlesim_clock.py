"""turtlesim has no /clock: its nodes run on the wall clock (rospy.Time.now() is never 0, logs carry one time),
so the wiki's time-based move works as it does on a real turtlesim, while robot runs keep /use_sim_time."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

NODES = Path(__file__).parent / "nodes"

pytestmark = pytest.mark.slow


def test_the_wiki_move_node_drives_its_distance_on_turtlesim(tmp_path):
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=6.0),
                   nodes=(NodeSpec(script=NODES / "wiki_move.py", stdin="1.0\n2.0\n1\n"),))
    result = run(spec, tmp_path / "run.mcap", tmp_path / "run.log")
    assert result.nodes[0].status == "exited", result.nodes[0].message
    assert "start time is zero: False wallclock: True" in (tmp_path / "run.log").read_text()
    recording = Recording.open(tmp_path / "run.mcap")
    truth = recording.ground_truth()
    # Its publisher connects 0.1 s after it is made while the node busy-loops (real rospy: 0.03-0.16 s, median
    # 0.10), so the first 0.1 s of its 1 m/s commands are lost, as on a real turtlesim: 1.9 m of the 2 m.
    assert truth.x[-1] - truth.x[0] == pytest.approx(1.9, abs=0.02)
    # turtlesim's own node publishes the world's topics (a robot's are Gazebo's)
    assert {t.callerid for t in recording.topics() if t.topic == "/turtle1/pose"} == {"/turtlesim"}


def test_robot_runs_keep_sim_time(tmp_path):
    script = tmp_path / "clock.py"
    script.write_text("import rospy\nrospy.init_node('c')\nprint('wallclock:', rospy.rostime.is_wallclock(), "
                      "rospy.get_param('/use_sim_time'))\n")
    spec = RunSpec(scenario=Scenario(duration=1.0), nodes=(NodeSpec(script=script),))
    run(spec, tmp_path / "run.mcap", tmp_path / "run.log")
    assert "wallclock: False True" in (tmp_path / "run.log").read_text()
