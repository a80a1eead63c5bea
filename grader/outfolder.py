"""A batch's output folder: one batch at a time, checked writable up front, and write failures told in one message.

The lock is an `flock` on a file in the folder: the kernel drops it when the batch holding it dies, so a killed
batch never leaves the folder locked.
"""
from __future__ import annotations

import contextlib
import errno
import fcntl
import os
import shutil
import socket
from pathlib import Path

LOCK_FILE = ".rosgrade-batch.lock"
PROBE_BYTES = 64 * 1024


class OutputFault(Exception):
    """Something in the output folder could not be written; the message says what, where and what to do."""


def describe(exc: OSError, path: Path, out: Path, need_bytes: int) -> str:
    """One clear sentence about a failed write: what could not be written, where, and why."""
    reason = exc.strerror or str(exc)
    if exc.errno in (errno.ENOSPC, errno.EDQUOT):
        free = free_bytes(out)
        return (f"could not write {path}: the disk holding {out} is full ({megabytes(free)} free; a student's results "
                f"need about {megabytes(need_bytes)}); free some space")
    if exc.errno == errno.ENOENT:
        return f"could not write {path}: it (or its folder) disappeared while the batch was running; do not move {out}"
    if exc.errno in (errno.EACCES, errno.EPERM, errno.EROFS):
        return f"could not write {path}: {reason}; choose an --out folder you can write to"
    return f"could not write {path}: {reason}"


def megabytes(count: int | None) -> str:
    return "an unknown amount" if count is None else f"{count / 1e6:.1f} MB"


def free_bytes(folder: Path) -> int | None:
    try:
        return shutil.disk_usage(folder).free
    except OSError:
        return None


class OutputLock:
    """Held while a batch writes into `out`; a second batch on the same folder is refused."""

    def __init__(self, out: Path) -> None:
        self.out = out
        self._fd: int | None = None

    def __enter__(self) -> OutputLock:
        path = self.out / LOCK_FILE
        try:
            fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        except OSError as exc:
            raise OutputFault(describe(exc, path, self.out, PROBE_BYTES)) from None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = os.pread(fd, 200, 0).decode("utf-8", "replace").strip() or "another process"
            os.close(fd)
            raise OutputFault(f"another rosgrade batch ({holder}) is writing into {self.out}; wait for it to finish "
                              "or choose another --out") from None
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"pid {os.getpid()} on {socket.gethostname()}".encode(), 0)
        self._fd = fd
        return self

    def __exit__(self, *exc_info: object) -> None:
        if self._fd is not None:
            os.close(self._fd)  # closing releases the flock; the file stays, harmless and reusable
            self._fd = None


def prepare(out: Path) -> None:
    """Create `out` and prove it can be written (a file is written, synced and removed) before anything is graded."""
    probe = out / ".rosgrade-write-test"
    try:
        out.mkdir(parents=True, exist_ok=True)
        fd = os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        try:
            os.write(fd, b"\0" * PROBE_BYTES)
            os.fsync(fd)
        finally:
            os.close(fd)
        probe.unlink()
    except OSError as exc:
        with contextlib.suppress(OSError):
            probe.unlink()
        raise OutputFault(describe(exc, out if not out.is_dir() else probe, out, PROBE_BYTES)) from None
