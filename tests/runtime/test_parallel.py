"""Runs carried out side by side: results in the caller's order, errors in their place, cores as allowed."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from grader import timing
from grader.runtime import cores, parallel
from grader.runtime.cores import available_cores
from grader.runtime.parallel import Run, WorkerError, run_all
from grader.runtime.session import RunError
from grader.runtime.spec import NodeSpec, RunResult, RunSpec
from sim import Scenario


def _runs(tmp_path: Path, durations: list[float]) -> list[Run]:
    return [Run(RunSpec(scenario=Scenario(duration=d), nodes=(NodeSpec(script=tmp_path / "n.py"),), name=f"r{i}"),
                tmp_path / f"r{i}.mcap", tmp_path / f"r{i}.log") for i, d in enumerate(durations)]


def _fake_run(spec: RunSpec, recording: Path, log: Path) -> RunResult:
    """Stands in for a real run: fails for duration 2, crashes for duration 3, else writes its recording."""
    if spec.scenario.duration == 2.0:
        raise RunError("could not start")
    if spec.scenario.duration == 3.0:
        raise ValueError("a bug of ours")
    recording.write_text(f"{spec.name} in {os.getpid()}")
    timing.count("runs")
    return RunResult(recording, log, 0.0, spec.scenario.duration, None, [], [])


@pytest.fixture()
def fake_run(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(parallel, "run", _fake_run)


@pytest.mark.parametrize("jobs", [1, 2, 3])
def test_results_come_back_in_the_callers_order(tmp_path: Path, fake_run: None, jobs: int) -> None:
    runs = _runs(tmp_path, [1.0, 5.0, 4.0, 6.0])
    results = run_all(runs, jobs)
    assert [r.ended_s for r in results] == [1.0, 5.0, 4.0, 6.0]
    assert all(item.recording.read_text().startswith(item.spec.name) for item in runs)


def test_parallel_runs_are_other_processes_and_start_longest_first(tmp_path: Path, fake_run: None) -> None:
    runs = _runs(tmp_path, [1.0, 5.0, 4.0, 6.0])
    started: list[str] = []
    run_all(runs, 2, lambda item: started.append(item.spec.name))
    assert started == ["r3", "r1", "r2", "r0"]
    assert not any(item.recording.read_text().endswith(f" {os.getpid()}") for item in runs)


def test_a_run_error_takes_the_runs_place(tmp_path: Path, fake_run: None) -> None:
    results = run_all(_runs(tmp_path, [1.0, 2.0, 4.0]), 2)
    assert isinstance(results[1], RunError) and str(results[1]) == "could not start"
    assert isinstance(results[0], RunResult) and isinstance(results[2], RunResult)


def test_a_bug_in_a_worker_is_raised_with_its_traceback(tmp_path: Path, fake_run: None) -> None:
    with pytest.raises(WorkerError, match="ValueError: a bug of ours"):
        run_all(_runs(tmp_path, [1.0, 3.0]), 2)


def test_worker_timings_are_added_to_the_parents(tmp_path: Path, fake_run: None) -> None:
    with timing.collect() as stages:
        run_all(_runs(tmp_path, [1.0, 4.0, 5.0]), 2)
    assert stages["# runs"] == 3.0


def test_available_cores_follows_affinity_and_the_tightest_cgroup_quota(tmp_path: Path,
                                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 1, 2, 3})
    monkeypatch.setattr(cores, "CGROUP_ROOT", tmp_path)
    monkeypatch.setattr(cores, "OWN_CGROUP", tmp_path / "self.cgroup")
    (tmp_path / "self.cgroup").write_text("0::/grading/job\n")
    job = tmp_path / "grading" / "job"
    job.mkdir(parents=True)
    assert available_cores() == 4  # no cpu.max anywhere
    (job / "cpu.max").write_text("max 100000\n")
    assert available_cores() == 4
    (tmp_path / "grading" / "cpu.max").write_text("200000 100000\n")  # a quota on the parent applies too
    assert available_cores() == 2
    (job / "cpu.max").write_text("50000 100000\n")  # Gradescope's half core
    assert available_cores() == 1


def test_available_cores_follows_a_cgroup_v1_cpu_quota(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 1})
    monkeypatch.setattr(cores, "CGROUP_ROOT", tmp_path)
    monkeypatch.setattr(cores, "OWN_CGROUP", tmp_path / "self.cgroup")
    (tmp_path / "self.cgroup").write_text("2:cpu,cpuacct:/docker/abc\n0::/\n")
    folder = tmp_path / "cpu" / "docker" / "abc"
    folder.mkdir(parents=True)
    (folder / "cpu.cfs_period_us").write_text("100000\n")
    (folder / "cpu.cfs_quota_us").write_text("-1\n")
    assert available_cores() == 2
    (folder / "cpu.cfs_quota_us").write_text("50000\n")
    assert available_cores() == 1
