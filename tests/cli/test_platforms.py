"""Platform outputs validate against the formats in grading-platforms.md, in success and in failure."""
from __future__ import annotations

import json
from pathlib import Path

import yaml

from grader.cli import main
from grader.platforms import github, gradescope, junit, prairielearn
from grader.reports.plots import Plot

from . import fakes
from .validators import (decode_github_output, validate_github_result, validate_gradescope, validate_junit,
                         validate_prairielearn)


def test_gradescope_results_validate():
    validate_gradescope(json.dumps(gradescope.gradescope_results(fakes.make_report(), 12.3)))


def test_gradescope_has_one_test_per_criterion_with_tags_numbers_and_visibility():
    tests = gradescope.gradescope_results(fakes.make_report())["tests"]
    assert [t["number"] for t in tests] == ["1.1", "1.2", "1.3", "2.1", "2.2"]
    assert tests[0]["tags"] == ["move_circle", "radius"] and tests[0]["output_format"] == "md"
    assert [t["visibility"] for t in tests][:3] == ["visible", "visible", "hidden"]


def test_gradescope_test_scores_add_up_to_the_total():
    report = fakes.make_report()
    data = gradescope.gradescope_results(report)
    assert sum(t.get("score", 0) for t in data["tests"]) == data["score"] == report.score
    assert sum(t.get("max_score", 0) for t in data["tests"]) == report.max_score


def test_gradescope_task_error_becomes_an_explanatory_test_carrying_its_points():
    data = validate_gradescope(json.dumps(gradescope.gradescope_results(fakes.make_report(square_status="error"))))
    problem = [t for t in data["tests"] if "error" in t["tags"]][0]
    assert problem["status"] == "failed" and problem["max_score"] == 10 and "ZeroDivisionError" in problem["output"]


def test_gradescope_failure_file_validates():
    data = validate_gradescope(json.dumps(gradescope.gradescope_failure("no scripts found")))
    assert data["score"] == 0 and data["tests"][0]["status"] == "failed"


def test_gradescope_placeholder_exists_while_grading(grading, submission, monkeypatch, capsys):
    seen: list[dict] = []

    def grade(sub, out, tasks=None, rubrics=None, jobs=1):
        seen.append(validate_gradescope(Path("results.json").read_text()))
        return fakes.make_report(str(sub))

    monkeypatch.setattr(fakes, "fake_grade_submission", grade)
    fakes.install(monkeypatch, "grader.grading", fakes.grading_module())
    assert main(["check", str(submission), "--out", "out", "--gradescope", "results.json"]) == 0
    assert "did not finish" in seen[0]["tests"][0]["output"]
    assert validate_gradescope(Path("results.json").read_text())["score"] == 14.5


def test_gradescope_file_is_valid_on_input_errors(grading, capsys):
    assert main(["check", "missing_pkg", "--gradescope", "results.json"]) == 2
    assert "no such file" in validate_gradescope(Path("results.json").read_text())["output"]


def test_github_result_tests_are_equal_units_passed_exactly_when_scored():
    report = fakes.make_report(radius_ok=False)
    result = validate_github_result(github.runner_result(report))
    unit = github.point_unit(report)
    assert {t["score"] for t in result["tests"] if t["status"] == "pass"} == {unit}
    assert {t["score"] for t in result["tests"] if t["status"] != "pass"} == {0.0}
    assert result["status"] == "fail"


def test_github_log_and_classroom_points_agree_with_partial_credit():
    report = fakes.make_report()  # 14.5 / 20 with a criterion at 2.5 / 5
    result = github.runner_result(report)
    assert github.classroom_points(result) == (report.score, report.max_score)
    assert github.log_points(result) == report.score


def test_github_points_round_to_the_unit_when_scores_are_odd():
    report = fakes.make_report()
    report.tasks[0].criteria[0].score = 3.297
    report.tasks[0].score = sum(c.score for c in report.tasks[0].criteria)
    report = report.total()
    result = github.runner_result(report)
    points, maximum = github.classroom_points(result)
    assert points == github.log_points(result) and maximum == report.max_score
    criteria = sum(len(t.criteria) for t in report.tasks)
    assert abs(points - report.score) <= criteria * github.point_unit(report) / 2 + 1e-9


def test_github_hidden_criterion_feedback_is_withheld():
    tests = github.runner_result(fakes.make_report())["tests"]
    assert all("SECRET" not in t["message"] for t in tests)
    assert "SECRET" not in github.step_summary(fakes.make_report())


def test_github_output_and_summary_go_to_the_actions_files(grading, submission, tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("GITHUB_OUTPUT", str(tmp_path / "gh_output"))
    monkeypatch.setenv("GITHUB_STEP_SUMMARY", str(tmp_path / "gh_summary"))
    assert main(["check", str(submission), "--out", "out", "--github-summary", "--github-result"]) == 0
    result = decode_github_output((tmp_path / "gh_output").read_text())
    assert github.log_points(result) == github.classroom_points(result)[0] == 14.5
    summary = (tmp_path / "gh_summary").read_text()
    assert "| ✅ | Stays within speed limits | 3 / 3 |" in summary and "artifact" in summary


def test_github_failure_result_round_trips(grading, tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("GITHUB_OUTPUT", str(tmp_path / "gh_output"))
    assert main(["check", "missing", "--github-result"]) == 2
    assert decode_github_output((tmp_path / "gh_output").read_text())["status"] == "error"


def test_github_workflow_example_wires_the_reporter():
    path = Path(github.__file__).with_name("github_workflow_example.yml")
    workflow = yaml.safe_load(path.read_text())
    job = workflow["jobs"]["run-autograding-tests"]
    grade = next(s for s in job["steps"] if s.get("id") == "rosgrade")
    reporter = next(s for s in job["steps"] if "grading-reporter" in s.get("uses", ""))
    assert "--github-result" in grade["run"] and "--task" in grade["run"] and reporter["with"]["runners"] == "rosgrade"
    assert reporter["env"]["ROSGRADE_RESULTS"] == "${{ steps.rosgrade.outputs.result }}"


def png_plot(name: str, size: int) -> Plot:
    return Plot("move_circle", "nominal", name, f"{name} plot", b"\x89PNG" + bytes(size))


def test_prairielearn_results_validate_with_inline_trajectory():
    data = validate_prairielearn(json.dumps(prairielearn.prairielearn_results(fakes.make_report(), [png_plot("path", 20_000)])))
    assert data["score"] == 14.5 / 20 and data["images"][0]["label"] == "path plot"
    assert data["tests"][0]["max_points"] == 4


def test_prairielearn_stays_under_1_mb_keeping_the_trajectory_first():
    plots = [png_plot("commands", 300_000), png_plot("path", 300_000), png_plot("printed", 300_000)]
    text = json.dumps(prairielearn.prairielearn_results(fakes.make_report(), plots))
    data = validate_prairielearn(text)
    assert [i["label"] for i in data["images"]] == ["path plot", "printed plot"]


def test_prairielearn_failure_is_not_gradable():
    data = prairielearn.prairielearn_failure("unreadable zip")
    assert data["gradable"] is False and data["score"] == 0


def test_prairielearn_hidden_feedback_is_withheld():
    assert "SECRET" not in json.dumps(prairielearn.prairielearn_results(fakes.make_report()))


def test_junit_parses_with_failures_for_lost_points():
    root = validate_junit(junit.junit_xml(fakes.make_report()))
    assert root.get("tests") == "5" and root.get("failures") == "2" and root.get("errors") == "0"


def test_junit_task_error_is_an_error_case():
    root = validate_junit(junit.junit_xml(fakes.make_report(square_status="timeout")))
    assert root.get("errors") == "1"


def test_junit_failure_document_parses(grading, capsys):
    assert main(["check", "missing", "--junit", "junit.xml"]) == 2
    assert validate_junit(Path("junit.xml").read_text()).get("errors") == "1"


def test_all_platform_files_from_one_check(grading, submission, capsys):
    argv = ["check", str(submission), "--out", "out", "--gradescope", "gs.json", "--prairielearn", "pl.json",
            "--junit", "j.xml"]
    assert main(argv) == 0
    validate_gradescope(Path("gs.json").read_text())
    validate_prairielearn(Path("pl.json").read_text())
    validate_junit(Path("j.xml").read_text())


def test_platforms_without_files_say_where_to_watch_the_replay_first():
    report = fakes.make_report(radius_ok=False, recordings=["move_circle/nominal.mcap"])
    pointer = "run `rosgrade check` on your package: its report.html replays every run"
    gradescope_output = gradescope.gradescope_results(report)["output"]
    prairielearn_output = prairielearn.prairielearn_results(report)["output"]
    assert "Watch first: move" in gradescope_output and "report.html replays every run" in gradescope_output
    assert pointer in prairielearn_output and "scenario 'nominal'" in prairielearn_output


def test_platforms_say_nothing_of_a_replay_when_nothing_was_recorded():
    report = fakes.make_report()
    assert "report.html" not in gradescope.gradescope_results(report)["output"]
    assert "report.html" not in prairielearn.prairielearn_results(report)["output"]
