"""sys.stdout / sys.stderr replacements that send every write to the grader as an OUTPUT frame (unbuffered)."""
from __future__ import annotations

import io

from .link import Link


class _OutputRaw(io.RawIOBase):
    """Binary end of a node stream: each write becomes OUTPUT frames at once, so a SIGKILL loses nothing."""

    def __init__(self, link: Link, stream: int, fd: int) -> None:
        super().__init__()
        self._link = link
        self._stream = stream
        self._fd = fd

    def writable(self) -> bool:
        return True

    def write(self, data) -> int:
        data = bytes(data)
        if data:
            self._link.send_output(self._stream, data)
        return len(data)

    def fileno(self) -> int:
        return self._fd

    def isatty(self) -> bool:
        return False


def make_stream(link: Link, stream: int, fd: int, errors: str) -> io.TextIOWrapper:
    """A text stream like Python's own (utf-8, ``.buffer``, ``.fileno()``) that writes through to the channel."""
    return io.TextIOWrapper(_OutputRaw(link, stream, fd), encoding="utf-8", errors=errors, write_through=True)
