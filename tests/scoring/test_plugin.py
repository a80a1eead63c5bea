"""Instructor plugin metrics: a function in a file beside the rubric, checked when the rubric loads, scored like a built-in."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from grader.metrics import RunData, Trajectory
from grader.rubric import RubricError, load_rubric, task_table
from grader.scoring import score_task

RUBRIC = '''
id = "spiral"
title = "Spiral outwards"
robot = "turtlebot3_waffle"

[[nodes]]
script = "spiral.py"

[[scenarios]]
name = "nominal"
duration = 30.0

[[criteria]]
id = "growth"
title = "The radius grows"
points = 2
metric = "{metric}"
quantity = "{quantity}"
params = {params}
tolerance = {{ bounds = [0.1, 1.0], margin = 0.1 }}
feedback.failed = "growth {{growth:.2f}} m"
'''

PLUGIN = '''
import numpy as np
from grader.metrics.plugin import metric

@metric(quantities=["growth", "turns"], params={"source": "ground_truth", "min_samples": 3})
def spiral_score(run, params):
    traj = run.trajectory(params.source)
    r = np.hypot(traj.x, traj.y)
    return {"growth": r[-1] - r[0], "turns": np.int64(2)}

@metric(quantities=["growth"])
def broken(run, params):
    return {"growth": 1 / 0}

def undeclared(run, params):
    return {"growth": 1.0}
'''


def _rubric(tmp_path: Path, metric: str = "my_metrics.py:spiral_score", quantity: str = "growth",
            params: str = "{}", plugin: str | None = PLUGIN, folder: str = "course") -> Path:
    directory = tmp_path / folder
    directory.mkdir(exist_ok=True)
    if plugin is not None:
        (directory / "my_metrics.py").write_text(plugin, encoding="utf-8")
    path = directory / "spiral.toml"
    path.write_text(RUBRIC.format(metric=metric, quantity=quantity, params=params), encoding="utf-8")
    return path


def _run(radii: list[float]) -> RunData:
    t = np.arange(len(radii), dtype=float)
    traj = Trajectory.of(t, radii, np.zeros(len(radii)), np.zeros(len(radii)), "ground_truth")
    return RunData(odometry=traj, ground_truth=traj)


def test_a_plugin_metric_scores_like_a_built_in(tmp_path: Path) -> None:
    rubric = load_rubric(_rubric(tmp_path))
    report = score_task(rubric, {"nominal": _run([0.0, 0.2, 0.5])})
    growth = report.criteria[0]
    assert growth.score == growth.max_score == 2
    assert growth.measured == {"growth": 0.5, "turns": 2, "judged_until_s": 2.0, "judged_until_ctrl_c": False}


def test_plugin_quantities_become_plain_values(tmp_path: Path) -> None:
    rubric = load_rubric(_rubric(tmp_path))
    measured = rubric.criteria[0].metric_def.measure(_run([0.0, 0.3]), rubric.criteria[0].metric_params)
    assert type(measured["turns"]) is int and type(measured["growth"]) is float


def test_plugin_params_are_validated_against_the_declaration(tmp_path: Path) -> None:
    rubric = load_rubric(_rubric(tmp_path, params='{ source = "odometry", min_samples = 5 }'))
    assert rubric.criteria[0].metric_params.min_samples == 5  # type: ignore[attr-defined]
    with pytest.raises(RubricError, match=r"params for metric .*min_sample.*[Ee]xtra"):
        load_rubric(_rubric(tmp_path, params="{ min_sample = 5 }"))
    with pytest.raises(RubricError, match="min_samples"):
        load_rubric(_rubric(tmp_path, params='{ min_samples = "many" }'))


def test_a_quantity_the_plugin_does_not_declare_is_a_load_error(tmp_path: Path) -> None:
    with pytest.raises(RubricError, match=r"quantity 'radius' is not measured by .*expected one of growth, turns"):
        load_rubric(_rubric(tmp_path, quantity="radius"))


@pytest.mark.parametrize("metric,plugin,message", [
    ("my_metrics.py", PLUGIN, 'must look like "my_metrics.py:function_name"'),
    ("my_metrics:spiral_score", PLUGIN, 'must look like "my_metrics.py:function_name"'),
    ("other.py:spiral_score", PLUGIN, "plugin file 'other.py' not found next to the rubric"),
    ("my_metrics.py:spiral", PLUGIN, "defines no 'spiral'; its metrics are: broken, spiral_score"),
    ("my_metrics.py:undeclared", PLUGIN, "is not declared as a metric; put @metric"),
    ("my_metrics.py:spiral_score", "def spiral_score(run, params:\n", "line 1: cannot be imported: SyntaxError"),
    ("my_metrics.py:spiral_score", "x = 1\nraise RuntimeError('no data')\n", "line 2: cannot be imported: RuntimeError"),
    ("my_metrics.py:f", "from grader.metrics.plugin import metric\n@metric(quantities=[])\ndef f(run, p): pass\n",
     "needs at least one quantity name"),
    ("my_metrics.py:f", "from grader.metrics.plugin import metric\n@metric(quantities=['a'], params={'w': [1]})\n"
     "def f(run, p): pass\n", "default must be a bool, int, float, str or None"),
    ("my_metrics.py:f", "from grader.metrics.plugin import metric\n@metric(quantities=['a'])\ndef f(run): pass\n",
     "must take two arguments (run, params)"),
], ids=["no_function", "no_py", "no_file", "no_name", "undecorated", "syntax", "import_crash", "no_quantities",
        "bad_default", "bad_signature"])
def test_load_time_errors_name_the_file_field_and_fix(tmp_path: Path, metric: str, plugin: str, message: str) -> None:
    folder = f"c{abs(hash((metric, plugin)))}"  # a fresh folder: each plugin file is imported once per process
    with pytest.raises(RubricError) as caught:
        load_rubric(_rubric(tmp_path, metric=metric, plugin=plugin, folder=folder))
    assert "criteria[0] ('growth').metric" in str(caught.value)
    assert message in str(caught.value)


def test_a_plugin_that_crashes_while_scoring_costs_only_its_criterion(tmp_path: Path) -> None:
    rubric = load_rubric(_rubric(tmp_path, metric="my_metrics.py:broken"))
    report = score_task(rubric, {"nominal": _run([0.0, 0.5])})
    assert report.criteria[0].score == 0
    assert "the rubric's metric broken failed (ZeroDivisionError" in report.criteria[0].feedback
    assert "my_metrics.py line" in report.criteria[0].feedback


def test_same_named_plugin_files_of_two_rubrics_do_not_collide(tmp_path: Path) -> None:
    other = PLUGIN.replace("r[-1] - r[0]", "0.0")
    first = load_rubric(_rubric(tmp_path, folder="a"))
    second = load_rubric(_rubric(tmp_path, plugin=other, folder="b"))
    run = _run([0.0, 0.5])
    assert first.criteria[0].metric_def.measure(run, first.criteria[0].metric_params)["growth"] == 0.5
    assert second.criteria[0].metric_def.measure(run, second.criteria[0].metric_params)["growth"] == 0.0


def test_task_table_adds_extra_files_and_folders_to_the_built_in_tasks(tmp_path: Path) -> None:
    path = _rubric(tmp_path)
    by_file, by_folder = task_table([path]), task_table([path.parent])
    assert "spiral" in by_file and "move_square" in by_file
    assert by_file.keys() == by_folder.keys()
    assert by_file["spiral"].source == path
    assert list(task_table([path], builtin=False)) == ["spiral"]


def test_task_table_rejects_an_id_defined_twice(tmp_path: Path) -> None:
    path = _rubric(tmp_path)
    copy = tmp_path / "again"
    copy.mkdir()
    (copy / "my_metrics.py").write_text(PLUGIN, encoding="utf-8")
    (copy / "spiral.toml").write_text(path.read_text(), encoding="utf-8")
    with pytest.raises(RubricError, match=r"task 'spiral' is already defined by .*course/spiral.toml"):
        task_table([path, copy])
    builtin = tmp_path / "move_square.toml"
    builtin.write_text(path.read_text().replace('id = "spiral"', 'id = "move_square"'), encoding="utf-8")
    (tmp_path / "my_metrics.py").write_text(PLUGIN, encoding="utf-8")
    with pytest.raises(RubricError, match=r"task 'move_square' is already defined by .*rubrics/move_square.toml"):
        task_table([builtin])


@pytest.mark.parametrize("entry,message", [
    ("missing.toml", "cannot read the rubric"),
    ("notes.txt", "expected a rubric .toml file or a folder of them"),
    ("empty", "holds no *.toml rubric files"),
])
def test_task_table_says_what_is_wrong_with_an_extra_entry(tmp_path: Path, entry: str, message: str) -> None:
    (tmp_path / "notes.txt").write_text("x", encoding="utf-8")
    (tmp_path / "empty").mkdir()
    with pytest.raises(RubricError, match=message.replace("*", r"\*")):
        task_table([tmp_path / entry])


def test_a_plugin_outside_a_rubric_file_is_refused() -> None:
    from grader.rubric import Criterion

    with pytest.raises(ValueError, match="can only be used in a rubric file"):
        Criterion.model_validate({"id": "a", "title": "a", "points": 1, "metric": "m.py:f", "quantity": "q",
                                  "tolerance": {"bounds": [0, 1]}})


@pytest.mark.parametrize("body,message", [
    ("return [1.0]", "returned list, not a dict"),
    ("return {'turns': 1}", "did not return growth"),
])
def test_a_plugin_that_returns_the_wrong_shape_is_named(tmp_path: Path, body: str, message: str) -> None:
    plugin = ("from grader.metrics.plugin import metric\n"
              f"@metric(quantities=['growth', 'turns'])\ndef spiral_score(run, params):\n    {body}\n")
    rubric = load_rubric(_rubric(tmp_path, plugin=plugin, folder=f"shape{abs(hash(body))}"))
    criterion = score_task(rubric, {"nominal": _run([0.0, 0.5])}).criteria[0]
    assert criterion.score == 0 and f"the rubric's metric spiral_score {message}" in criterion.feedback
