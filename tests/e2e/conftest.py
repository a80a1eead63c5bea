"""Shared, expensive fixtures for end-to-end grading: each submission is graded once per test session."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.report import SubmissionReport

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = ROOT / "reference_solutions"
REFERENCE_TURTLESIM = ROOT / "reference_solutions_turtlesim"
EXAMPLES = ROOT / "submissions_example"


@pytest.fixture(scope="session")
def reference_dir() -> Path:
    return REFERENCE


@pytest.fixture(scope="session")
def turtlesim_reference_dir() -> Path:
    return REFERENCE_TURTLESIM


@pytest.fixture(scope="session")
def examples_dir() -> Path:
    return EXAMPLES


@pytest.fixture(scope="session")
def graded(tmp_path_factory):
    """grade(path, tasks) -> SubmissionReport, cached so a submission is run only once."""
    cache: dict[tuple[Path, tuple[str, ...]], SubmissionReport] = {}

    def grade(path: Path, tasks: tuple[str, ...] = ()) -> SubmissionReport:
        key = (path, tasks)
        if key not in cache:
            out = tmp_path_factory.mktemp(path.name)
            cache[key] = grade_submission(path, out, list(tasks) or None)
        return cache[key]

    return grade
