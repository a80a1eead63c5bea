"""rosgrade's rospy mimic hears and speaks on the topics real roscpp's mimic would, for the roslaunch tutorial's remap
of ``input``/``output``, remaps of the full topic names, both at once, namespaces, private and root targets.

The names were measured with Debian's roscpp 1.15.15 (``ros1_mimic_real.py``, recorded in
``ros1_mimic_roscpp_names.json``); where roscpp can be built the measurement is repeated. rosgrade's side is one run
with a mimic per case: the grader publishes a Pose on the topic roscpp would subscribe to, and the Twist of its
velocities must come out on the topic roscpp would publish on, and nowhere else.
"""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

from grader.recording import Recording
from grader.rubric import GRADER_NODES
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario
from sim.scenario import PublicationSpec

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ros1_mimic_real import CASES, measure, recorded, unavailable_reason  # noqa: E402

LOST = "/rosgrade/lost"  # where the recording keeps what a node published that nothing subscribed to


def _pose(index: int) -> tuple[float, float]:
    """The (linear, angular) velocity sent to case ``index``: distinct for each case, exact in Pose's float32."""
    return float(index + 1), -(index + 1) / 4


@pytest.mark.realros
@pytest.mark.slow
def test_real_roscpp_resolves_mimics_topics_as_recorded() -> None:
    if (reason := unavailable_reason()) is not None:
        pytest.skip(f"{reason}: compared with the recorded names only")
    assert measure() == recorded()


@pytest.mark.slow
def test_rosgrade_mimic_hears_and_speaks_where_roscpps_does(tmp_path: Path) -> None:
    names = recorded()
    sends = [PublicationSpec(t=0.5, topic=names[case.node][1], type="turtlesim/Pose",
                             values={"linear_velocity": _pose(i)[0], "angular_velocity": _pose(i)[1]})
             for i, case in enumerate(CASES)]
    nodes = tuple(NodeSpec(script=GRADER_NODES / "turtle_mimic.py", args=case.args, ros_namespace=case.namespace,
                           provided=True) for case in CASES)
    result = run(RunSpec(scenario=Scenario(robot="turtlesim", duration=1.5, publications=sends), nodes=nodes),
                 tmp_path / "run.mcap", tmp_path / "run.log")
    assert [node.name for node in result.nodes] == [names[case.node][0] for case in CASES]
    recording = Recording.open(tmp_path / "run.mcap")
    said = {}
    for info in recording.topics():
        if info.type == "geometry_msgs/Twist":
            topic = info.topic.removeprefix(LOST)
            said[info.callerid, topic] = [(m.linear.x, m.angular.z) for _, m in recording.messages(info.topic)]
    assert said == {(names[case.node][0], names[case.node][2]): [_pose(i)] for i, case in enumerate(CASES)}
