"""Planning a task reads the submission's interfaces once: its runs carry them, and their findings are the task's."""
from __future__ import annotations

import shutil
from pathlib import Path

from grader.grading import _plan_task
from grader.rubric import load_rubrics
from tests.interfaces.workspaces import package

EXAMPLE = Path(__file__).resolve().parents[2] / "reference_solutions_ros2_cmake"


def test_a_task_s_runs_carry_the_submission_s_interfaces(tmp_path: Path) -> None:
    submission = tmp_path / "submission"
    shutil.copytree(EXAMPLE, submission / "src")
    package(submission, "loop_interfaces", {"msg/Node.msg": "Node next\n"})
    rubric = load_rubrics()["move_circle"]
    plan = _plan_task(submission, rubric, tmp_path / "out")
    spec = plan.runs[0].spec
    assert spec.flavour == "ros2"
    assert "number_game_interfaces/srv/MyNumberGame" in spec.interfaces.services
    assert "number_game_interfaces/msg/Guess" in spec.interfaces.payload["messages"]
    assert any("loop_interfaces/Node -> loop_interfaces/Node contains itself" in f for f in plan.findings)
    assert all(run.spec.interfaces is spec.interfaces for run in plan.runs)
