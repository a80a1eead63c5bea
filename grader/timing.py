"""Where grading's wall time goes: seconds summed per named stage, kept only while a benchmark asks for them.

Off (the default) every call is a test of one global, so grading pays next to nothing for it; `rosgrade bench`
turns it on with `collect()`. Stages nest, and each is counted exclusively: a stage's seconds leave out those of
the stages timed inside it, so the stages add up to the whole. An `absorb` stage keeps what is timed inside it
(node start-up includes the wait for the node's imports). Counters (frames, runs) ride along so per-frame costs
can be derived. A grading worker process collects its own and hands them back (`snapshot`/`merge`).
"""
from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from types import TracebackType

_seconds: dict[str, float] | None = None
_counts: dict[str, int] = {}
_stack: list[_Stage] = []


class _Stage:
    """A timed block; a no-op one stands in when nothing is being collected."""

    __slots__ = ("name", "absorb", "started")

    def __init__(self, name: str, absorb: bool) -> None:
        self.name, self.absorb, self.started = name, absorb, 0.0

    def __enter__(self) -> None:
        self.started = time.perf_counter()
        _stack.append(self)

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None) -> None:
        elapsed = time.perf_counter() - self.started
        _stack.remove(self)
        add(self.name, elapsed)


class _Off:
    __slots__ = ()

    def __enter__(self) -> None:
        return None

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None) -> None:
        return None


_OFF = _Off()


def enabled() -> bool:
    """Whether stages are being collected in this process."""
    return _seconds is not None


@contextmanager
def collect() -> Iterator[dict[str, float]]:
    """Collect stage seconds while the block runs; the dict yielded holds them afterwards (counters as `# name`)."""
    global _seconds, _counts
    _seconds, _counts = {}, {}
    totals: dict[str, float] = {}
    try:
        yield totals
    finally:
        totals.update(snapshot())
        _seconds, _counts = None, {}
        _stack.clear()


def restart() -> None:
    """Forget what was collected so far, keeping collection on (a forked worker starts from zero)."""
    global _seconds, _counts
    if _seconds is not None:
        _seconds, _counts = {}, {}
    _stack.clear()


def add(stage: str, seconds: float) -> None:
    """Add wall seconds to a stage, taking them from the stage they were timed in (nothing when not collecting)."""
    if _seconds is None:
        return
    if _stack:
        if any(outer.absorb for outer in _stack):
            return  # an enclosing stage keeps them
        outer = _stack[-1].name
        _seconds[outer] = _seconds.get(outer, 0.0) - seconds
    _seconds[stage] = _seconds.get(stage, 0.0) + seconds


def count(name: str, n: int = 1) -> None:
    """Add to a counter (nothing when not collecting)."""
    if _seconds is not None:
        _counts[name] = _counts.get(name, 0) + n


def stage(name: str, absorb: bool = False) -> _Stage | _Off:
    """A context manager timing its block as stage `name`."""
    return _OFF if _seconds is None else _Stage(name, absorb)


def snapshot() -> dict[str, float]:
    """What this process collected so far: stages by name, counters as `# name`."""
    if _seconds is None:
        return {}
    return {**_seconds, **{f"# {name}": float(n) for name, n in _counts.items()}}


def merge(collected: dict[str, float]) -> None:
    """Add what another process collected (a `snapshot`) to this one's."""
    if _seconds is None:
        return
    for name, value in collected.items():
        if name.startswith("# "):
            count(name[2:], int(value))
        else:
            _seconds[name] = _seconds.get(name, 0.0) + value
