"""What has been read from a recording file, kept while the file is unchanged: scoring reads a run's series, then the
report's plots ask for the same ones, and opening and decoding the file again cost about as much as drawing them.

A memo is found by the file's path and matched by its size, modification time and CRC-32 (a re-run that rewrote the
file in the same clock tick still differs in content), so a changed file is always read afresh. Results are shared
between the readers of one file: their numpy arrays are made read-only and lists are handed out as copies.
"""
from __future__ import annotations

import dataclasses
import functools
import os
import stat
import zlib
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

import numpy as np

KEPT_FILES = 32  # a task's runs and then its plots: a few files at a time; each memo holds arrays, not messages
F = TypeVar("F", bound=Callable[..., Any])


@dataclass
class FileMemo:
    """One file's header facts (format, truncation, metadata) and the results read from it so far; ``identity`` is
    the file's when it was read (None: a file that is not kept, such as a bag folder)."""

    identity: tuple[int, int, int] | None
    format: str
    truncated: str | None
    metadata: dict[str, dict[str, Any]]
    results: dict[tuple, Any] = field(default_factory=dict)


_memos: OrderedDict[str, FileMemo] = OrderedDict()


def identity(path: Path) -> tuple[int, int, int] | None:
    """(size, mtime ns, CRC-32) of a regular file, or None for anything else (a bag folder, a missing file)."""
    try:
        info = os.stat(path)
        if not stat.S_ISREG(info.st_mode):
            return None
        with open(path, "rb") as file:
            crc = zlib.crc32(file.read())
    except OSError:
        return None
    return info.st_size, info.st_mtime_ns, crc


def find(path: Path, found: tuple[int, int, int] | None) -> FileMemo | None:
    """The memo of the file at ``path`` if it was made from the same content (``found``: its identity now)."""
    if found is None:
        return None
    key = str(path.resolve())
    memo = _memos.get(key)
    if memo is None or memo.identity != found:
        return None
    _memos.move_to_end(key)
    return memo


def keep(path: Path, memo: FileMemo) -> None:
    """Remember ``memo`` for the file at ``path``, forgetting the least recently used beyond KEPT_FILES."""
    key = str(path.resolve())
    _memos[key] = memo
    _memos.move_to_end(key)
    while len(_memos) > KEPT_FILES:
        _memos.popitem(last=False)


def forget_all() -> None:
    """Drop every memo (tests that rewrite files in place use it to start clean)."""
    _memos.clear()


def remembered(method: F) -> F:
    """Memoize a Recording method's result in its file's memo, keyed by the method and its arguments."""

    @functools.wraps(method)
    def wrapper(self, *args, **kwargs):
        memo: FileMemo = self._memo
        key = (method.__name__, args, tuple(sorted(kwargs.items())))
        if key not in memo.results:
            memo.results[key] = _shared(method(self, *args, **kwargs))
        return _handed_out(memo.results[key])

    return wrapper  # type: ignore[return-value]


def _shared(value: Any) -> Any:
    """The value as it is kept: arrays of a dataclass read-only, a list as a tuple."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        for item in dataclasses.fields(value):
            array = getattr(value, item.name)
            if isinstance(array, np.ndarray):
                array.flags.writeable = False
        return value
    if isinstance(value, list):
        return tuple(value)
    return value


def _handed_out(value: Any) -> Any:
    return list(value) if isinstance(value, tuple) else value
