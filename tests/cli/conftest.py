"""Fixtures for the CLI tests: fake grading, rubric, scoring and recording modules and a clean working folder."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from . import fakes


@pytest.fixture
def grading(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Path:
    """Install the fake grading and rubric modules; returns the call log (one line per grade_submission call)."""
    fakes.install(monkeypatch, "grader.grading", fakes.grading_module())
    fakes.install(monkeypatch, "grader.rubric", fakes.rubric_module())
    fakes.install(monkeypatch, "grader.scoring", fakes.scoring_module())
    fakes.install(monkeypatch, "grader.recording", fakes.recording_module())
    log = tmp_path / "calls.log"
    monkeypatch.setenv(fakes.CALL_LOG_ENV, str(log))
    monkeypatch.setenv(fakes.BATCH_PID_ENV, str(os.getpid()))
    monkeypatch.delenv("GITHUB_STEP_SUMMARY", raising=False)
    monkeypatch.delenv("GITHUB_OUTPUT", raising=False)
    monkeypatch.setenv("COLUMNS", "200")  # one table row per line, so assertions can match cell text
    monkeypatch.chdir(tmp_path)
    return log


@pytest.fixture
def submission(tmp_path: Path) -> Path:
    """A catkin package with one script."""
    package = tmp_path / "alice_pkg"
    (package / "scripts").mkdir(parents=True)
    (package / "scripts" / "move_circle.py").write_text("import rospy\n")
    return package


def calls(log: Path) -> list[str]:
    """The submissions graded so far, in call order."""
    return log.read_text().split() if log.exists() else []
