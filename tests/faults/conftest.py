"""Fixtures for the fault-injection suite: the CLI's fake grading (fast, deterministic) and a class of students."""
from __future__ import annotations

from pathlib import Path

import pytest

from cli import fakes
from cli.test_batch import make_students, rows
from cli.conftest import grading  # noqa: F401  (the fake grading, rubric, scoring and recording modules)

STUDENTS = ["ann", "ben_nap", "cat.zip", "dan_wobbly", "gil_crash"]


def make_class(root: Path, names: list[str] = STUDENTS) -> Path:
    """One submission per name: a package folder, or a .zip for names ending in .zip."""
    return make_students(root, names)


def grades(out: Path) -> list[dict[str, str]]:
    return rows(out)


@pytest.fixture
def klass(tmp_path: Path) -> Path:
    return make_class(tmp_path)


@pytest.fixture(scope="session")
def reference(tmp_path_factory: pytest.TempPathFactory) -> str:
    """grades.csv of an uninterrupted batch of the class (what every faulted-then-resumed run must end with)."""
    from grader.cli import main

    root = tmp_path_factory.mktemp("reference")
    with pytest.MonkeyPatch.context() as patch:
        for name, module in (("grader.grading", fakes.grading_module()), ("grader.rubric", fakes.rubric_module()),
                             ("grader.scoring", fakes.scoring_module()),
                             ("grader.recording", fakes.recording_module())):
            fakes.install(patch, name, module)
        patch.delenv(fakes.CALL_LOG_ENV, raising=False)
        assert main(["batch", str(make_class(root)), "--out", str(root / "out"), "-j", "2"]) == 0
    return (root / "out" / "grades.csv").read_text()
