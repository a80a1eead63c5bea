"""The param_circle task end to end: the grader sets the node's radius at run time as ``ros2 param set`` does; the
ament_cmake reference earns full marks, its recording holds the grader's SetParameters requests, the node's answers
and its /parameter_events, re-scores identically and repeats bit for bit; a node that reads the parameter once, one
that refuses the value and one under another name each lose radius_follows with feedback naming why."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.metrics.run import service_calls
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "reference_solutions_ros2_cmake" / "part3_beyond_basics"
ONCE = ROOT / "submissions_example" / "vic_ros2_param_once"
REFERENCE = (PACKAGE / "scripts" / "param_circle.py").read_text()


@pytest.fixture(scope="module")
def reference(graded):
    return graded(PACKAGE, ("param_circle",)).tasks[0]


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    """A copy of the reference script with one change, as a one-file submission."""
    assert old in REFERENCE
    folder = tmp_path / "student"
    folder.mkdir()
    (folder / "param_circle.py").write_text(REFERENCE.replace(old, new))
    return folder


def _scores(task) -> dict[str, bool]:
    return {c.id: c.score == c.max_score for c in task.criteria}


def _feedback(task, criterion: str) -> str:
    return next(c.feedback for c in task.criteria if c.id == criterion)


def test_the_reference_scores_full_marks(reference):
    assert reference.status == "graded", reference.message
    assert reference.score == reference.max_score, {c.id: c.feedback for c in reference.criteria}
    assert _feedback(reference, "radius_follows") == (
        "The robot drove circles of 0.50, 1.20, 0.80 m as radius was set to 0.50, 1.20, 0.80 m.")


def test_the_recording_holds_the_sets_the_answers_and_the_parameter_events(reference):
    recording = Recording.open(reference.recordings[0])
    calls = service_calls(recording)
    assert [(round(c.t - 2.0, 3), c.service, [(p.name, p.value.type, p.value.double_value)
                                               for p in c.request["parameters"]],
             [(r.successful, r.reason) for r in c.response["results"]]) for c in calls] == [
        (10.0, "/param_circle/set_parameters", [("radius", 3, 1.2)], [(True, "")]),
        (20.0, "/param_circle/set_parameters", [("radius", 3, 0.8)], [(True, "")])]
    callers = {(i.topic.rsplit("/", 1)[1], i.callerid, i.origin) for i in recording.topics()
               if i.topic.startswith("/rosgrade/service/")}
    assert callers == {("request", "/rosgrade", "grader"), ("response", "/param_circle", "node")}
    # the declarations went out before discovery; each set after it is an event, stamped when the node applied it
    events = [(t_ns, m) for _, t_ns, m in recording.messages_on({"/parameter_events"})]
    assert [(round(t_ns / 1e9 - 2.0, 3), m.node, [(p.name, p.value.double_value) for p in m.changed_parameters],
             m.new_parameters, m.stamp.sec + m.stamp.nanosec / 1e9 == t_ns / 1e9) for t_ns, m in events] == [
        (10.0, "/param_circle", [("radius", 1.2)], [], True), (20.0, "/param_circle", [("radius", 0.8)], [], True)]
    assert reference.diagnostics == ["param_circle.py published 297 messages on /cmd_vel "
                                     "(geometry_msgs/msg/TwistStamped)."]


def test_the_recording_rescores_identically_and_repeats_bit_for_bit(reference, tmp_path):
    recordings = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    again = score_task(load_rubrics()["param_circle"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in reference.criteria]
    second = grade_submission(PACKAGE, tmp_path, ["param_circle"]).tasks[0]
    assert Path(second.recordings[0]).read_bytes() == Path(reference.recordings[0]).read_bytes()


def test_reading_the_parameter_once_loses_radius_follows_and_says_why(graded):
    task = graded(ONCE, ("param_circle",)).tasks[0]
    assert _scores(task) == {"radius_follows": False, "shutdown_stop": True}
    feedback = _feedback(task, "radius_follows")
    assert feedback.startswith("The robot drove circles of 0.50, 0.50, 0.50 m while radius was set to 0.50, 1.20, "
                               "0.80 m: from 10.0 s to 20.0 s, with radius = 1.2, the robot drove a circle of "
                               "radius 0.50 m.")
    assert "not once in `__init__`" in feedback


def test_a_refused_value_reaches_the_setter_and_the_feedback(tmp_path):
    refusing = _variant(tmp_path, '        self.declare_parameter(name="radius", value=0.5)  # m\n', (
        '        self.declare_parameter(name="radius", value=0.5)  # m\n'
        '        self.add_on_set_parameters_callback(lambda params: SetParametersResult(\n'
        '            successful=all(p.value <= 1.0 for p in params), reason="at most 1 m"))\n'))
    script = refusing / "param_circle.py"
    script.write_text("from rcl_interfaces.msg import SetParametersResult\n" + script.read_text())
    task = grade_submission(refusing, tmp_path / "out", ["param_circle"]).tasks[0]
    calls = service_calls(Recording.open(task.recordings[0]))
    assert [[(r.successful, r.reason) for r in c.response["results"]] for c in calls] == [
        [(False, "at most 1 m")], [(True, "")]]
    assert _scores(task) == {"radius_follows": False, "shutdown_stop": True}
    assert ('your node refused `radius = 1.2`: "at most 1 m"' in _feedback(task, "radius_follows"))


def test_a_node_under_another_name_is_never_reached_and_told_the_name(tmp_path):
    task = grade_submission(_variant(tmp_path, 'super().__init__("param_circle")', 'super().__init__("circle")'),
                            tmp_path / "out", ["param_circle"]).tasks[0]
    assert _scores(task) == {"radius_follows": False, "shutdown_stop": True}
    assert "nothing served /param_circle/set_parameters. Name the node 'param_circle'" in _feedback(
        task, "radius_follows")


def test_a_node_that_dies_at_the_first_set_is_told_it_had_ended(tmp_path):
    task = grade_submission(_variant(tmp_path, '        self.declare_parameter(name="radius", value=0.5)  # m\n', (
        '        self.declare_parameter(name="radius", value=0.5)  # m\n'
        '        self.add_on_set_parameters_callback(lambda params: 1 / 0)\n')), tmp_path / "out",
        ["param_circle"]).tasks[0]
    feedback = _feedback(task, "radius_follows")
    assert "`ros2 param set /param_circle radius 0.8` never reached your node: it had ended by then (10.0 s" in feedback
    assert "ZeroDivisionError: division by zero" in feedback
