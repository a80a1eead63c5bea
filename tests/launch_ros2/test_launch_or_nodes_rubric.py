"""A rubric with both [launch] and [[nodes]] (figure_of_eight) starts the launch file when the submission holds it
and the script otherwise, and says what is missing when it holds neither."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import _launch_nodes
from grader.rubric import load_rubric
from grader.runtime import ScriptNotFound

ROOT = Path(__file__).resolve().parents[2]
RUBRIC = load_rubric(ROOT / "rubrics" / "figure_of_eight.toml")


def test_the_team_package_s_launch_file_is_started() -> None:
    (nodes, _, scripts), _ = _launch_nodes(ROOT / "reference_solutions_ros2_cmake" / "com2009_team1", RUBRIC)
    assert scripts[0].name == "task1.launch.py"
    assert [spec.script.name for spec in nodes] == ["figure_eight.py"]


def test_a_rospy_script_without_a_launch_file_runs_as_the_rubric_s_node() -> None:
    (nodes, _, scripts), _ = _launch_nodes(ROOT / "reference_solutions", RUBRIC)
    assert [path.name for path in scripts] == ["figure_eight.py"]
    assert [spec.flavour for spec in nodes] == ["ros1"]


def test_a_submission_with_neither_is_told_both_names(tmp_path: Path) -> None:
    (tmp_path / "notes.txt").write_text("nothing to run\n")
    with pytest.raises(ScriptNotFound, match=r"no file named figure_eight.py in the submission, and no package "
                                             r"named com2009_team\* in the submission"):
        _launch_nodes(tmp_path, RUBRIC)
