"""`rosgrade rubric check/try`: an instructor's rubric with a plugin metric, validated and graded end to end."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from grader.cli import EXIT_ERROR, EXIT_OK, main

ROOT = Path(__file__).resolve().parents[2]
SPIRAL = ROOT / "rubrics" / "examples" / "spiral"


@pytest.fixture()
def spiral(tmp_path: Path) -> Path:
    """A copy of the spiral example (rubric, plugin, node) that a test may break."""
    folder = tmp_path / "course"
    shutil.copytree(SPIRAL, folder)
    return folder


def test_check_prints_what_it_will_run_and_score(capsys) -> None:
    assert main(["rubric", "check", str(ROOT / "rubrics" / "figure_of_eight.toml")]) == EXIT_OK
    out = capsys.readouterr().out
    for text in ("task 'figure_of_eight'", "world_start", "at 20 s", "loop_directions", "shutdown_stop",
                 "9 criteria worth 24 points over 5 scenarios"):
        assert text in out


def test_check_json_names_the_plugin_metric_and_every_scored_quantity(capsys) -> None:
    assert main(["rubric", "check", str(SPIRAL / "spiral.toml"), "--json"]) == EXIT_OK
    plan = json.loads(capsys.readouterr().out)
    assert plan["id"] == "spiral" and plan["sim_seconds"] == 32.0
    assert plan["criteria"][0]["metric"] == "my_metrics.py:spiral_score"
    assert plan["criteria"][0]["scored"] == [{"quantity": "growth", "tolerance": "in [0.3, 1] ±0.3"}]


@pytest.mark.parametrize("edit,message", [
    (("my_metrics.py", '"growth", "turns"', '"turns"'), "quantity 'growth' is not measured by"),
    (("my_metrics.py", "def spiral_score(run, params):", "def spiral_score(run, params)"), "SyntaxError"),
    (("spiral.toml", '{ source = "odometry" }', '{ sorce = "odometry" }'), "sorce"),
    (("spiral.toml", "my_metrics.py:spiral_score", "my_metric.py:spiral_score"), "'my_metric.py' not found"),
], ids=["undeclared_quantity", "syntax_error", "unknown_param", "missing_file"])
def test_a_broken_plugin_is_one_line_before_anything_runs(spiral: Path, tmp_path: Path, capsys,
                                                           edit: tuple[str, str, str], message: str) -> None:
    name, old, new = edit
    target = spiral / name
    assert old in target.read_text()
    target.write_text(target.read_text().replace(old, new))
    out = tmp_path / "out"
    for argv in (["rubric", "check", str(spiral / "spiral.toml")],
                 ["rubric", "try", str(spiral / "spiral.toml"), str(spiral / "spiral.py"), "--out", str(out)]):
        assert main(argv) == EXIT_ERROR
        err = capsys.readouterr().err
        assert err.startswith(f"rosgrade: error: {spiral / 'spiral.toml'}: criteria[0] ('radius_growth')")
        assert message in err and "Traceback" not in err
    assert not out.exists()


@pytest.mark.slow
def test_try_grades_a_submission_with_the_plugin_metric(spiral: Path, tmp_path: Path, capsys) -> None:
    out = tmp_path / "out"
    assert main(["rubric", "try", str(spiral / "spiral.toml"), str(spiral / "spiral.py"), "--out", str(out),
                 "--json"]) == EXIT_OK
    report = json.loads(capsys.readouterr().out)
    growth = report["tasks"][0]["criteria"][0]
    assert report["tasks"][0]["id"] == "spiral" and growth["id"] == "radius_growth"
    assert growth["score"] == growth["max_score"] == 3, growth["feedback"]
    assert 0.3 < growth["measured"]["growth"] < 1.0 and growth["measured"]["turns"] > 1.5
    assert (out / "report.json").is_file() and (out / "spiral" / "nominal.mcap").is_file()


@pytest.mark.slow
def test_try_reports_a_plugin_that_crashes_on_the_run_as_the_criterion_feedback(spiral: Path, tmp_path: Path,
                                                                               capsys) -> None:
    plugin = spiral / "my_metrics.py"
    plugin.write_text(plugin.read_text().replace("quarter = len(radius) // 4", "quarter = len(radius) // 0"))
    assert main(["rubric", "try", str(spiral / "spiral.toml"), str(spiral / "spiral.py"), "--out",
                 str(tmp_path / "out"), "--json"]) == EXIT_OK
    growth = json.loads(capsys.readouterr().out)["tasks"][0]["criteria"][0]
    assert growth["score"] == 0
    assert "the rubric's metric spiral_score failed (ZeroDivisionError" in growth["feedback"]


def test_try_rejects_a_submission_path_that_does_not_exist(tmp_path: Path, capsys) -> None:
    assert main(["rubric", "try", str(SPIRAL / "spiral.toml"), str(tmp_path / "nothing.py")]) == EXIT_ERROR
    assert "no such file or folder" in capsys.readouterr().err


def test_rubric_check_shows_where_turtlesim_really_starts_and_what_each_run_types(capsys):
    assert main(["rubric", "check", str(Path(__file__).resolve().parents[2] / "rubrics" / "turtle_move.toml"),
                 "--json"]) == 0
    plan = json.loads(capsys.readouterr().out)
    runs = {s["name"]: s for s in plan["scenarios"]}
    assert runs["nominal"]["start_pose"] == pytest.approx([5.544445, 5.544445, 0.0], abs=1e-5)  # the window's centre
    assert runs["backwards"]["stdin"].endswith("0\n") and runs["backwards"]["params"]["forward"] is False
