"""add_two_ints and fibonacci grade the rospy tutorials' servers with the ROS 2 tasks' rubrics and criterion ids: the
wiki's beginner_tutorials AddTwoInts server (its own srv, called as its catkin type) and the actionlib tutorial's
Fibonacci server (goals sent on actionlib's topics, its statuses read as their ROS 2 twins) score full marks,
re-score identically and repeat bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

REFERENCE = Path(__file__).resolve().parents[2] / "reference_solutions_ros1_tutorials"
TASKS = ("add_two_ints", "fibonacci")


@pytest.fixture(scope="module")
def reports(graded):
    return {task.id: task for task in graded(REFERENCE, TASKS).tasks}


@pytest.mark.parametrize("task", TASKS)
def test_the_rospy_reference_scores_full_marks(reports, task):
    report = reports[task]
    assert report.status == "graded", report.message
    assert report.score == report.max_score, {c.id: c.feedback for c in report.criteria}


def test_the_service_is_called_as_the_packages_own_catkin_type(reports):
    recording = Recording.open(reports["add_two_ints"].recordings[0])
    calls = RunData.from_recording(recording, start_time=2.0).service_calls
    assert [(c.request, c.response) for c in calls] == [
        ({"a": 2, "b": 3}, {"sum": 5}), ({"a": -7, "b": 4}, {"sum": -3}), ({"a": 4000000000, "b": 1}, {"sum": 4000000001})]
    assert {(i.topic, i.type) for i in recording.topics() if i.topic.startswith("/rosgrade/service/")} == {
        ("/rosgrade/service/add_two_ints/request", "beginner_tutorials/AddTwoIntsRequest"),
        ("/rosgrade/service/add_two_ints/response", "beginner_tutorials/AddTwoIntsResponse")}


def test_actionlib_goals_read_back_with_ros2_statuses(reports):
    recording = Recording.open(reports["fibonacci"].recordings[0])
    first, second = RunData.from_recording(recording, start_time=2.0).action_goals
    # ACTIVE -> EXECUTING (2), SUCCEEDED -> 4; the cancelled one PREEMPTING -> CANCELING (3), PREEMPTED -> CANCELED (5);
    # each goal's client connects to the server 50 ms after it starts (rospy's connect delay), then sends
    assert (first.t, first.goal, first.accepted, first.statuses, first.result) == (
        2.55, {"order": 5}, True, (2, 4), {"sequence": [0, 1, 1, 2, 3, 5]})
    assert first.feedback_t == (2.55, 3.55, 4.55, 5.55)  # one a second, as the tutorial sleeps
    assert (second.t, second.cancel_t, second.statuses, second.final_status) == (7.55, 9.0, (2, 3, 5), 5)
    channels = {(i.topic, i.callerid, i.origin) for i in recording.topics() if i.topic.startswith("/fibonacci/")}
    assert channels == {("/fibonacci/goal", "/rosgrade", "grader"), ("/fibonacci/cancel", "/rosgrade", "grader"),
                        *((f"/fibonacci/{topic}", "/fibonacci", "node") for topic in ("status", "feedback", "result"))}


@pytest.mark.parametrize("task", TASKS)
def test_the_recordings_rescore_identically_and_repeat_bit_for_bit(reports, task, tmp_path):
    report = reports[task]
    recordings = {Path(p).stem: Recording.open(p) for p in report.recordings}
    again = score_task(load_rubrics()[task], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in report.criteria]
    second = grade_submission(REFERENCE, tmp_path, [task]).tasks[0]
    assert Path(second.recordings[0]).read_bytes() == Path(report.recordings[0]).read_bytes()
