"""Open what a student handed in (a .py file, a package, a workspace or a .zip) as a folder, safely."""
from __future__ import annotations

import os
import shutil
import stat
import tempfile
import zipfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path, PurePosixPath

from grader.runtime.confine import exited

MAX_UNPACKED_BYTES = 200 * 1024 * 1024
MAX_MEMBERS = 20_000
STAGE_PREFIX = "rosgrade-grade-"  # a batch's submissions are unpacked at <tmp>/rosgrade-grade-<content hash>
OWNER_FILE = ".owner-pid"  # in such a folder: the grading process that made it (to clean up after a kill)
MAX_RATIO = 200  # a member that expands more than this is treated as a zip bomb


class SubmissionError(Exception):
    """The submission cannot be used as it is; the message says what is wrong and what to do."""


def _safe_members(archive: zipfile.ZipFile, name: str) -> list[zipfile.ZipInfo]:
    members = archive.infolist()
    if len(members) > MAX_MEMBERS:
        raise SubmissionError(f"{name} holds {len(members)} files (limit {MAX_MEMBERS}); zip only your package.")
    total = 0
    for info in members:
        path = PurePosixPath(info.filename.replace("\\", "/"))
        if path.is_absolute() or ".." in path.parts:
            raise SubmissionError(f"{name} contains the unsafe path {info.filename!r}; it was not unpacked.")
        if stat.S_ISLNK(info.external_attr >> 16):
            raise SubmissionError(f"{name} contains a symbolic link ({info.filename}); zip real files only.")
        total += info.file_size
        if info.compress_size and info.file_size / info.compress_size > MAX_RATIO and info.file_size > 1 << 20:
            raise SubmissionError(f"{name}: {info.filename} expands {info.file_size // info.compress_size}x; "
                                  "refusing a likely zip bomb.")
    if total > MAX_UNPACKED_BYTES:
        raise SubmissionError(f"{name} unpacks to {total >> 20} MiB (limit {MAX_UNPACKED_BYTES >> 20} MiB).")
    return members


def unzip(path: Path, into: Path) -> None:
    """Unpack a .zip into a folder after checking it is safe (no escaping paths, links or zip bombs)."""
    try:
        with zipfile.ZipFile(path) as archive:
            for info in _safe_members(archive, path.name):
                target = into / PurePosixPath(info.filename.replace("\\", "/"))
                if info.is_dir():
                    target.mkdir(parents=True, exist_ok=True)
                    continue
                target.parent.mkdir(parents=True, exist_ok=True)
                with archive.open(info) as src, open(target, "wb") as dst:
                    shutil.copyfileobj(src, dst)
                mode = (info.external_attr >> 16) & 0o777
                if mode:
                    target.chmod(mode | stat.S_IRUSR | stat.S_IWUSR)
    except (zipfile.BadZipFile, EOFError, OSError, NotImplementedError) as exc:
        raise SubmissionError(f"{path.name} is not a readable .zip file ({exc}); re-create the archive.") from None


def links_leaving(root: Path, paths: list[Path]) -> list[Path]:
    """Symbolic links among ``paths`` and inside those that are folders whose targets lie outside ``root``.

    Such a link would grade someone else's file (``move_circle.py -> ../classmate/move_circle.py``) or run and quote
    a file the student may not read; the grader refuses the task instead of following it. Links within the
    submission are fine. At most MAX_MEMBERS entries are looked at.
    """
    base = root.resolve()
    found: list[Path] = []
    seen = 0

    def check(path: Path) -> None:
        if path.is_symlink() and not path.resolve().is_relative_to(base) and path not in found:
            found.append(path)

    for path in paths:
        check(path)
        if path.is_symlink() or not path.is_dir():
            continue
        for folder, dirs, files in os.walk(path):
            for name in sorted(dirs + files):
                seen += 1
                if seen > MAX_MEMBERS:
                    return found
                check(Path(folder) / name)
    return found


@contextmanager
def open_submission(path: Path) -> Iterator[Path]:
    """Yield a folder (or a single .py file) holding the submission; a .zip is unpacked into a temporary folder."""
    if not path.exists():
        raise SubmissionError(f"{path} does not exist.")
    if path.is_file() and path.suffix.lower() == ".zip":
        with tempfile.TemporaryDirectory(prefix="rosgrade-sub-") as tmp:
            unzip(path, Path(tmp))
            yield Path(tmp)
        return
    if path.is_file() and path.suffix != ".py":
        raise SubmissionError(f"{path.name} is neither a .py script, a folder nor a .zip file.")
    yield path


def claim(folder: Path) -> None:
    """Mark folder as this process's, so that it can be removed once this process is gone (see remove_if_abandoned)."""
    (folder / OWNER_FILE).write_text(str(os.getpid()))


def remove_if_abandoned(folder: Path) -> bool:
    """Remove a claimed folder whose owner process is gone (killed, with its machine or its Dask worker).

    True when the folder is not there any more. An owner that is a zombie counts as gone: a grading process whose
    Dask worker was killed stays one until whoever inherited it reaps it.
    """
    try:
        owner = int((folder / OWNER_FILE).read_text())
    except (OSError, ValueError):
        return not folder.exists()  # absent, or not claimed (yet)
    try:
        os.kill(owner, 0)
    except ProcessLookupError:
        pass
    except PermissionError:  # alive, as another user
        return False
    else:
        if not exited(owner):
            return False
    shutil.rmtree(folder, ignore_errors=True)
    return not folder.exists()
