"""A rubric as bytes: what a batch grades with from start to end, shipped as is to any grader process, and hashed.

A report is stamped with the hash of the rubric file (and the plugin files it uses), so a resumed batch knows
which reports another rubric made. Grader processes elsewhere (Dask workers) load these bytes, not their own
copy, so the whole class is graded with the rubric the instructor has.
"""
from __future__ import annotations

import hashlib
import importlib
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from grader.report import RubricStamp


class RubricFileError(Exception):
    """A rubric's file (or a plugin file it names) cannot be read."""


@dataclass(frozen=True)
class RubricFile:
    """A rubric as bytes, so a grader process anywhere (a Dask worker) grades with exactly the instructor's rubric."""

    source: str  # the file it was read from, named in reports
    text: bytes
    plugins: tuple[tuple[str, bytes], ...] = ()  # the plugin metric files it names, by path beside it

    @property
    def task_id(self) -> str:
        """The task id (rubric files are named after their task)."""
        return Path(self.source).stem

    @property
    def sha256(self) -> str:
        """Hash of the rubric and its plugin files: a report with another hash was made with another rubric."""
        digest = hashlib.sha256(self.text)
        for name, data in self.plugins:
            digest.update(b"\0" + name.encode("utf-8") + b"\0" + data)
        return digest.hexdigest()


def rubric_file(rubric: Any) -> RubricFile:
    """Read the rubric's file and the plugin files it uses; RubricFileError when they cannot be read."""
    if rubric.source is None:
        raise RubricFileError(f"rubric {rubric.id!r} was not read from a file, so reports cannot name it")
    source = Path(rubric.source)
    names = sorted({c.metric.split(":", 1)[0] for c in rubric.criteria if ":" in c.metric})
    try:
        return RubricFile(str(source), source.read_bytes(),
                          tuple((name, (source.parent / name).read_bytes()) for name in names))
    except OSError as exc:
        raise RubricFileError(f"{source}: cannot read the rubric or its plugin files: {exc.strerror or exc}") from None


def rubric_files(rubrics: Iterable[Any]) -> tuple[RubricFile, ...]:
    """The files of these rubrics, read once (what a batch grades with from start to end)."""
    return tuple(rubric_file(r) for r in rubrics)


def load_rubric_files(files: Iterable[RubricFile], folder: Path) -> dict[str, Any]:
    """Validate rubrics handed over as bytes, by task id (written under `folder` first, beside their plugins)."""
    rubrics: dict[str, Any] = {}
    for index, file in enumerate(files):
        home = folder / str(index)
        home.mkdir(parents=True)
        for name, data in file.plugins:
            (home / name).parent.mkdir(parents=True, exist_ok=True)
            (home / name).write_bytes(data)
        path = home / f"{file.task_id}.toml"
        path.write_bytes(file.text)
        rubrics[file.task_id] = importlib.import_module("grader.rubric").load_rubric(path)
    return rubrics


def stamp(rubric: Any, file: RubricFile | None) -> RubricStamp | None:
    """The rubric stamp for a task's report; None for a rubric built in code (it has no file to name)."""
    if file is None:
        try:
            file = rubric_file(rubric)
        except RubricFileError:
            return None
    return RubricStamp(file=file.source, sha256=file.sha256, scenarios=[s.name for s in rubric.scenarios])
