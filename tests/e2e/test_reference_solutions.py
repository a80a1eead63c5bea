"""Every reference solution, written as a student following the course would, earns full marks in every scenario."""
from __future__ import annotations

import pytest

from grader.rubric import load_rubrics

pytestmark = pytest.mark.slow

# ROS 2-only tasks have their references in ROS 2 packages, graded in their own tests (test_add_two_ints.py,
# test_param_circle.py, test_number_game.py, test_number_game_client.py, test_fibonacci.py, test_fibonacci_client.py,
# test_explore_forward.py, test_reference_turtlesim_ros2.py, test_add_two_ints_client.py).
ROS2_ONLY = {"add_two_ints", "param_circle", "number_game", "number_game_client", "fibonacci", "fibonacci_client",
             "explore_forward", "turtle_spawn_draw", "add_two_ints_client", "turtle_rotate_absolute"}
RUBRICS = {task: rubric for task, rubric in load_rubrics().items() if task not in ROS2_ONLY}
TASKS = sorted(RUBRICS)
# The TurtleBot course's solutions and the turtlesim course's live in separate folders.
COURSES = {"robot": sorted(t for t, r in RUBRICS.items() if r.robot != "turtlesim"),
           "turtlesim": sorted(t for t, r in RUBRICS.items() if r.robot == "turtlesim")}


@pytest.fixture(scope="module")
def course_report(graded, reference_dir, turtlesim_reference_dir):
    """course_report(course): the report on that course's reference folder, graded once and only when asked for."""
    folders = {"robot": reference_dir, "turtlesim": turtlesim_reference_dir}
    return lambda course: graded(folders[course])


@pytest.fixture
def task_result(course_report):
    """task_result(task): that task's result, from the folder of its course."""
    def result(task):
        course = "turtlesim" if task in COURSES["turtlesim"] else "robot"
        return next(t for t in course_report(course).tasks if t.id == task)
    return result


@pytest.mark.parametrize("course", sorted(COURSES))
def test_every_task_is_found_from_the_script_names(course_report, course):
    assert sorted(t.id for t in course_report(course).tasks) == COURSES[course]


@pytest.mark.parametrize("task", TASKS)
def test_reference_scores_full_marks(task_result, task):
    result = task_result(task)
    assert result.status == "graded", result.message
    lost = {c.id: c.feedback for c in result.criteria if c.score < c.max_score}
    assert lost == {}
    assert result.score == result.max_score > 0


@pytest.mark.parametrize("task", TASKS)
def test_reference_runs_raise_no_exception(task_result, task):
    result = task_result(task)
    assert not [d for d in result.diagnostics if "uncaught" in d or "never called" in d]


@pytest.mark.parametrize("task", TASKS)
def test_rescoring_the_recordings_gives_exactly_the_live_result(task_result, task):
    from pathlib import Path

    from grader.recording import Recording
    from grader.scoring import score_task

    live = task_result(task)
    recordings = {Path(p).stem: Recording.open(p) for p in live.recordings}
    again = score_task(load_rubrics()[task], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in live.criteria]


def test_a_ros1_bag_without_ground_truth_is_scored_from_odometry(task_result, tmp_path):
    from pathlib import Path

    from rosbags.rosbag1 import Writer
    from rosbags.typesys import Stores, get_typestore

    from grader.recording import Recording
    from grader.scoring import score_task

    live = task_result("move_circle")
    source = Recording.open(next(p for p in live.recordings if Path(p).stem == "nominal"))
    store = get_typestore(Stores.ROS1_NOETIC)
    bag = tmp_path / "real_robot.bag"
    with Writer(bag) as writer:
        for topic, kind in (("/cmd_vel", "geometry_msgs/msg/Twist"), ("/odom", "nav_msgs/msg/Odometry")):
            connection = writer.add_connection(topic, kind, typestore=store)
            for t_ns, msg in source.messages(topic):
                writer.write(connection, t_ns, store.serialize_ros1(msg, kind))
    recording = Recording.open(bag)
    assert recording.ground_truth() is None
    result = score_task(load_rubrics()["move_circle"].restricted_to(["nominal"]), {"nominal": recording})
    radius = next(c for c in result.criteria if c.id == "radius")
    assert radius.score == radius.max_score
    assert any("ground truth" in note for note in result.diagnostics)
