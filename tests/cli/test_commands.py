"""`rosgrade tasks`, `score`, `bench` and `gradescope-package`."""
from __future__ import annotations

import importlib
import io
import json
import tarfile
import types
import zipfile
from pathlib import Path

import pytest

from grader.cli import main

from . import fakes
from .validators import validate_gradescope


def test_tasks_lists_rubrics_with_points_and_criteria(grading, capsys):
    assert main(["tasks"]) == 0
    out = capsys.readouterr().out
    assert "move_circle" in out and "Circle radius (4)" in out and "[hidden]" in out


def test_tasks_json(grading, capsys):
    assert main(["tasks", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data[0]["id"] == "move_circle" and data[0]["criteria"][2]["visibility"] == "hidden"


def test_score_uses_the_scenario_from_metadata(grading, capsys):
    Path("run1.mcap").write_bytes(b"MCAP")
    assert main(["score", "run1.mcap", "--task", "move_circle", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["tasks"][0]["diagnostics"] == ["scenarios: nominal"] and report["score"] == 7


def test_score_ros1_bag_is_nominal_and_says_it_has_no_ground_truth(grading, capsys):
    Path("old.bag").write_bytes(b"#ROSBAG")
    assert main(["score", "old.bag", "--task", "move_circle"]) == 0
    out, err = capsys.readouterr()
    assert "no ground truth" in err and "Circle radius" in out


def test_score_unknown_task_is_exit_2(grading, capsys):
    Path("run1.mcap").write_bytes(b"MCAP")
    assert main(["score", "run1.mcap", "--task", "nope"]) == 2


def test_score_unreadable_recording_is_exit_2_with_one_line(grading, capsys):
    Path("bad.mcap").write_bytes(b"garbage")
    assert main(["score", "bad.mcap", "--task", "move_circle"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "not an MCAP or bag file" in err


def test_score_two_recordings_of_one_scenario_is_exit_2(grading, capsys):
    Path("a.mcap").write_bytes(b"MCAP")
    Path("b.mcap").write_bytes(b"MCAP")
    assert main(["score", "a.mcap", "b.mcap", "--task", "move_circle"]) == 2


def bench_module() -> types.ModuleType:
    module = types.ModuleType("sim.bench")
    module.physics_benchmark = lambda robot="turtlebot3_waffle", sim_seconds=60.0: {
        "robot": robot, "sim_seconds": sim_seconds, "rtf": 184.2, "cpu_rtf": 200.0,
        "raw_steps_per_s": 185000.0}
    return module


def runtime_bench_module(calls: list) -> types.ModuleType:
    module = types.ModuleType("grader.runtime.bench")

    def runtime_benchmark(move_circle=None, repeats=3, move_circle_ros2=None):
        calls.append(move_circle if move_circle_ros2 is None else (move_circle, move_circle_ros2))
        return {"sim_seconds": 40.0, "move_circle_wall_s_median": 0.48, "busy_loop_sim_s_per_wall_s": 34.2,
                "move_circle_ros2_over_ros1": 1.19}

    module.runtime_benchmark = runtime_benchmark
    return module


def test_bench_prints_physics_and_node_run_figures(grading, monkeypatch, capsys):
    calls: list = []
    fakes.install(monkeypatch, "sim.bench", bench_module())
    fakes.install(monkeypatch, "grader.runtime.bench", runtime_bench_module(calls))
    assert main(["bench", "--seconds", "5"]) == 0
    out = capsys.readouterr().out
    assert "rtf" in out and "busy_loop_sim_s_per_wall_s" in out
    assert calls == [None]


def test_bench_times_the_rclpy_move_circle_beside_the_rospy_one(grading, monkeypatch, capsys, tmp_path):
    calls: list = []
    fakes.install(monkeypatch, "sim.bench", bench_module())
    fakes.install(monkeypatch, "grader.runtime.bench", runtime_bench_module(calls))
    ros2 = tmp_path / "pkg" / "pkg" / "move_circle.py"
    ros2.parent.mkdir(parents=True)
    ros2.write_text("import rclpy\n")
    assert main(["bench", "--seconds", "5", "--reference-ros2", str(tmp_path / "pkg")]) == 0
    assert calls == [(None, ros2)]
    assert "move_circle_ros2_over_ros1" in capsys.readouterr().out


def check_bench_module(calls: list) -> types.ModuleType:
    """The real check_bench figures, with the timed checks replaced by fixed ones."""
    real = importlib.import_module("grader.check_bench")
    module = types.ModuleType("grader.check_bench")
    module.load_average = lambda: "0.10 0.20 0.30"

    def best_of(submission, jobs, repeats):
        calls.append((submission, jobs, repeats))
        stages = {"node start-up": 2.0, "physics and sensors": 3.0, "plots": 1.0}
        return real.CheckTiming(jobs, 8.0 / jobs, 7.5, 920.0, 10, 4000, stages, 30.0, 30.0)

    module.best_of = best_of
    return module


def test_bench_times_a_whole_check_at_j1_and_jn(grading, monkeypatch, tmp_path, capsys):
    calls: list = []
    checks: list = []
    fakes.install(monkeypatch, "sim.bench", bench_module())
    fakes.install(monkeypatch, "grader.runtime.bench", runtime_bench_module(calls))
    fakes.install(monkeypatch, "grader.check_bench", check_bench_module(checks))
    (tmp_path / "refs").mkdir()
    (tmp_path / "refs" / "move_circle.py").write_text("import rospy\n")
    assert main(["bench", "--reference", str(tmp_path / "refs"), "-j", "2", "--repeats", "2", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["physics"]["rtf"] == 184.2 and data["runtime"]["move_circle_wall_s_median"] == 0.48
    assert calls == [tmp_path / "refs" / "move_circle.py"]
    assert checks == [(tmp_path / "refs", 1, 2), (tmp_path / "refs", 2, 2)]
    single, double = data["check"]
    assert single["sim_s_per_wall_s"] == 115.0 and single["of_physics_rtf"] == round(115.0 / 184.2, 3)
    assert double["wall_s"] == 4.0 and double["of_physics_rtf"] == round(230.0 / 184.2, 3)
    # per CPU second, against physics per CPU second: 920 sim-s in 7.5 CPU-s against 200x
    assert single["of_physics_cpu_rtf"] == round(920.0 / 7.5 / 200.0, 3)
    # the -j 1 stages add up to its wall time: what no stage holds is "other"
    assert sum(single["stages_s"].values()) == pytest.approx(8.0)
    assert data["load_average_before"] == "0.10 0.20 0.30"


def test_bench_physics_figure_is_the_fastest_of_samples_before_and_after_the_checks(grading, monkeypatch, tmp_path,
                                                                                    capsys):
    rtfs = iter([150.0, 160.0, 184.2, 90.0])  # two before the checks, two after: the machine sped up, then slowed
    module = types.ModuleType("sim.bench")
    module.physics_benchmark = lambda robot="turtlebot3_waffle", sim_seconds=60.0: {"rtf": next(rtfs), "cpu_rtf": 1.0}
    fakes.install(monkeypatch, "sim.bench", module)
    fakes.install(monkeypatch, "grader.check_bench", check_bench_module([]))
    (tmp_path / "refs").mkdir()
    assert main(["bench", "--reference", str(tmp_path / "refs"), "-j", "1", "--no-node-runs", "--repeats", "2",
                 "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["physics"]["rtf"] == 184.2 and data["physics"]["rtf_samples"] == "150 160 184 90"
    assert data["check"][0]["of_physics_rtf"] == round(115.0 / 184.2, 3)


def test_bench_prints_the_stage_table_and_the_physics_ratio(grading, monkeypatch, tmp_path, capsys):
    fakes.install(monkeypatch, "sim.bench", bench_module())
    fakes.install(monkeypatch, "grader.check_bench", check_bench_module([]))
    (tmp_path / "refs").mkdir()
    assert main(["bench", "--reference", str(tmp_path / "refs"), "-j", "1", "--no-node-runs"]) == 0
    out = capsys.readouterr().out
    assert "node start-up" in out and "physics and sensors" in out and "Of physics RTF" in out
    assert "0.62" in out  # 115 sim-s per wall-s against 184.2x


def test_bench_reference_that_does_not_exist_is_exit_2(grading, monkeypatch, capsys):
    fakes.install(monkeypatch, "sim.bench", bench_module())
    assert main(["bench", "--reference", "nowhere", "--no-node-runs"]) == 2
    assert "nowhere does not exist" in capsys.readouterr().err


def test_gradescope_package_has_setup_run_autograder_and_sdist(grading, capsys):
    assert main(["gradescope-package", "--task", "move_circle", "--task", "move_square", "--out", "ag.zip"]) == 0
    with zipfile.ZipFile("ag.zip") as archive:
        names = archive.namelist()
        assert {"setup.sh", "run_autograder", "README.md"} <= set(names)
        run = archive.read("run_autograder").decode()
        setup = archive.read("setup.sh").decode()
        assert run.startswith("#!") and setup.startswith("#!")
        assert archive.getinfo("run_autograder").external_attr >> 16 & 0o111
        assert "rosgrade check" in run and "--task move_circle --task move_square" in run and "--gradescope" in run
        assert "/autograder/results/results.json" in run
        fallback = run.split("<<'JSON'\n")[1].split("\nJSON\n")[0]
        validate_gradescope(fallback)
        sdist = next(n for n in names if n.endswith(".tar.gz"))
        assert f"pip install --no-cache-dir /autograder/source/{sdist}" in setup
        with tarfile.open(fileobj=io.BytesIO(archive.read(sdist))) as tar:
            members = tar.getnames()
    assert "rosgrade-0.1.0/pyproject.toml" in members and "rosgrade-0.1.0/grader/cli.py" in members
    assert not any("__pycache__" in m for m in members)


def test_gradescope_package_rejects_unknown_tasks(grading, capsys):
    assert main(["gradescope-package", "--task", "nope", "--out", "ag.zip"]) == 2
    assert not Path("ag.zip").exists()


def test_gradescope_package_needs_a_task(grading):
    with pytest.raises(SystemExit):
        main(["gradescope-package", "--out", "ag.zip"])
