"""A script that fits a TurtleBot task and a turtlesim task (move_circle.py) is graded as the one its topics name."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import _present_tasks
from grader.rubric import load_rubrics

NODE = '''#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist
rospy.init_node("circle")
pub = rospy.Publisher({topic!r}, Twist, queue_size=10)
'''


@pytest.fixture(scope="module")
def rubrics():
    return load_rubrics()


def submission(tmp_path: Path, **scripts: str) -> Path:
    for name, topic in scripts.items():
        (tmp_path / f"{name}.py").write_text(NODE.format(topic=topic))
    return tmp_path


@pytest.mark.parametrize("topic", ["turtle1/cmd_vel", "/turtle1/cmd_vel"])
def test_move_circle_on_a_turtles_topic_is_the_turtlesim_circle(tmp_path, rubrics, topic) -> None:
    assert _present_tasks(submission(tmp_path, move_circle=topic), rubrics) == ["turtle_circle"]


@pytest.mark.parametrize("topic", ["/cmd_vel", "cmd_vel"])
def test_move_circle_on_cmd_vel_is_the_turtlebot_circle(tmp_path, rubrics, topic) -> None:
    assert _present_tasks(submission(tmp_path, move_circle=topic), rubrics) == ["move_circle"]


def test_each_script_keeps_its_own_task_when_both_are_there(tmp_path, rubrics) -> None:
    folder = submission(tmp_path, move_circle="/cmd_vel", turtle_circle="turtle1/cmd_vel")
    assert sorted(_present_tasks(folder, rubrics)) == ["move_circle", "turtle_circle"]


def test_a_task_named_explicitly_is_graded_whatever_the_topic(tmp_path, rubrics) -> None:
    from grader.grading import _locate

    folder = submission(tmp_path, move_circle="/cmd_vel")
    script, _ = _locate(folder, rubrics["turtle_circle"].nodes[0], only_node=True)
    assert script.name == "move_circle.py"


@pytest.mark.parametrize("topic,task", [("/cmd_vel", "move_circle"), ("turtle1/cmd_vel", "turtle_circle")])
def test_a_batch_chooses_the_circle_task_its_students_topics_name(tmp_path, rubrics, topic, task) -> None:
    from grader.batch import choose_tasks
    from grader.roster import Student

    students = []
    for name in ("ana", "bo"):
        (tmp_path / name).mkdir()
        students.append(Student(key=name, name=name, path=submission(tmp_path / name, move_circle=topic)))
    chosen, why = choose_tasks(None, rubrics, students, tmp_path / "out")
    assert chosen == [task], why
