"""The students in a batch folder: plain folders and .zip files, or the downloads of Moodle, Canvas and Gradescope.

An LMS names each submission after the student (Moodle ``Jane Doe_123_assignsubmission_file_/x.zip``, Canvas
``doejane_123_456_move_circle.py``, Gradescope ``submission_789/`` with ``submission_metadata.yml``); the gradebook
shows that name, and each student gets an output folder (`key`) that is unique and safe on any file system.
"""
from __future__ import annotations

import io
import re
import zipfile
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

MOODLE = re.compile(r"^(?P<name>.+?)_(?P<id>\d+)_assignsubmission_(?P<kind>[a-z]+)_?$")
CANVAS = re.compile(r"^(?P<name>[^_]+?)(?:_late)?_(?P<id>\d+)_(?P<file_id>\d+)_(?P<file>.+)$")
CANVAS_REUPLOAD = re.compile(r"^(?P<stem>.+?)-(?P<n>\d+)(?P<suffix>\.[^.]+)$")  # Canvas renames a re-upload x-1.py
GRADESCOPE_METADATA = "submission_metadata.yml"
_UNSAFE = re.compile(r"[^\w.-]+")


class RosterError(Exception):
    """The batch folder cannot be read as a set of submissions; the message says why."""


@dataclass(frozen=True)
class Student:
    """One student's submission: a folder, a .zip or a script, or (Canvas) several loose files."""

    key: str  # output folder name: unique in the batch
    name: str  # the student's name as the LMS gives it (the folder or file name otherwise)
    path: Path  # what was handed in; for loose files, the first of them
    files: tuple[tuple[str, Path], ...] = ()  # loose files by the name the student gave them

    def pack(self) -> bytes:
        """The submission as zip bytes (a .zip as it is; files in name order, with fixed dates, for the rest)."""
        if not self.files and self.path.is_file() and self.path.suffix.lower() == ".zip":
            return self.path.read_bytes()
        if self.files:
            members = list(self.files)
        elif self.path.is_file():
            members = [(self.path.name, self.path)]
        else:
            inside = self.path.resolve()
            # A link out of the submission is left out: its target is someone else's file, not the student's.
            members = [(p.relative_to(self.path).as_posix(), p) for p in sorted(self.path.rglob("*"))
                       if p.is_file() and p.resolve().is_relative_to(inside)]
        buffer = io.BytesIO()
        with zipfile.ZipFile(buffer, "w") as archive:
            for name, source in members:
                info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
                info.external_attr = (source.stat().st_mode & 0o777) << 16
                info.compress_type = zipfile.ZIP_DEFLATED
                archive.writestr(info, source.read_bytes())
        return buffer.getvalue()


def find_students(folder: Path, exclude: Path | None = None) -> list[Student]:
    """The submissions in folder, by key: Gradescope's export, Moodle folders, Canvas files, plain entries."""
    if not folder.is_dir():
        raise RosterError(f"{folder} is not a folder")
    if (folder / GRADESCOPE_METADATA).is_file():
        return _gradescope(folder)
    entries = [e for e in sorted(folder.iterdir())
               if not e.name.startswith((".", "_")) and not (exclude is not None and e.resolve() == exclude.resolve())]
    students: list[Student] = []
    canvas: dict[tuple[str, str], list[tuple[str, Path]]] = {}
    for entry in entries:
        moodle = MOODLE.match(entry.name) if entry.is_dir() else None
        loose = CANVAS.match(entry.name) if entry.is_file() else None
        if moodle:
            if moodle["kind"] == "file":
                students.append(_moodle(entry, moodle["name"], moodle["id"]))
        elif loose:
            canvas.setdefault((loose["name"], loose["id"]), []).append((loose["file"], entry))
        elif entry.is_dir() or entry.suffix.lower() == ".zip":
            students.append(Student(_safe(entry.stem if entry.is_file() else entry.name), entry.name if entry.is_dir()
                                    else entry.stem, entry))
    students += [_canvas(name, user_id, files) for (name, user_id), files in canvas.items()]
    return _unique_keys(students)


def _moodle(folder: Path, name: str, user_id: str) -> Student:
    """Moodle puts each student's files in a folder; a single .zip in it is the submission itself."""
    inside = [p for p in folder.iterdir() if not p.name.startswith(".")]
    zips = [p for p in inside if p.is_file() and p.suffix.lower() == ".zip"]
    return Student(_safe(f"{name}_{user_id}"), name, zips[0] if len(inside) == 1 and zips else folder)


def _canvas(name: str, user_id: str, files: list[tuple[str, Path]]) -> Student:
    """Canvas flattens every file to name_userid_fileid_file; the latest re-upload of a file name wins."""
    latest: dict[str, tuple[int, Path]] = {}
    for original, path in files:
        reupload = CANVAS_REUPLOAD.match(original)
        base, version = (reupload["stem"] + reupload["suffix"], int(reupload["n"])) if reupload else (original, 0)
        if base not in latest or version > latest[base][0]:
            latest[base] = (version, path)
    key = _safe(f"{name}_{user_id}")
    if len(latest) == 1:
        (base, (_, path)), = latest.items()
        if path.suffix.lower() == ".zip":
            return Student(key, name, path)
    chosen = tuple(sorted((base, path) for base, (_, path) in latest.items()))
    return Student(key, name, chosen[0][1], chosen)


def _gradescope(folder: Path) -> list[Student]:
    """Gradescope's "Export submissions": submission_<id>/ folders, named in submission_metadata.yml."""
    names = gradescope_names((folder / GRADESCOPE_METADATA).read_text("utf-8", errors="replace"))
    students = [Student(entry.name, names.get(entry.name, entry.name), entry)
                for entry in sorted(folder.iterdir()) if entry.is_dir() and entry.name.startswith("submission_")]
    if not students:
        raise RosterError(f"{folder} has {GRADESCOPE_METADATA} but no submission_<id> folders")
    return students


def gradescope_names(metadata: str) -> dict[str, str]:
    """Submitters by submission folder, from the metadata file (Ruby-style YAML: ``:name: Jane Doe``).

    Read line by line rather than with a YAML library: only these two keys are needed, and the file is small.
    """
    names: dict[str, list[str]] = {}
    current: str | None = None
    for line in metadata.splitlines():
        top = re.match(r"^:?(submission_\d+):\s*$", line)
        if top:
            current = top.group(1)
            names[current] = []
            continue
        person = re.match(r"^\s*-?\s*:name:\s*(.+?)\s*$", line)
        if person and current is not None:
            names[current].append(person.group(1).strip("'\""))
    return {key: " & ".join(people) for key, people in names.items() if people}


def _safe(text: str) -> str:
    return _UNSAFE.sub("_", text).strip("._") or "student"


def _unique_keys(students: Iterable[Student]) -> list[Student]:
    """Sort by key; a key used twice (alice/ beside alice.zip) gets the entry's full name, then a counter."""
    taken: dict[str, Student] = {}
    for student in sorted(students, key=lambda s: (s.key, s.path.name)):
        key = student.key
        if key in taken:
            key = _safe(student.path.name)
        count = 2
        while key in taken:
            key = f"{student.key}_{count}"
            count += 1
        taken[key] = Student(key, student.name, student.path, student.files)
    return list(taken.values())
