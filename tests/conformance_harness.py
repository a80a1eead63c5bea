"""What the rospy and rclpy conformance suites share: masking of probe outputs, the caches of real and rosgrade runs,
and the two comparisons (ours against real runs; either side against a case's measured lines).

A suite (tests/conformance for rospy, tests/conformance_ros2 for rclpy) brings its probes, how it runs them on each
side and what it masks beyond this (rospy's sim-time log stamps, rclpy's ANSI colours and volatile lines).
"""
from __future__ import annotations

import re
import time
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any, Protocol

import pytest

PROBE_PATH = re.compile(r"(?:[^\s'\"():,]*/)?(p\d\d_[A-Za-z0-9_]+\.py)")
ADDRESS = re.compile(r"0x[0-9a-fA-F]{6,}")
_REF = re.compile(r"^#REF (-?\d+\.\d+)\s*$")
_FRAME = re.compile(r'^(\s*)File "([^"]+)", line \d+, in (.+)$')
_CARET = re.compile(r"^\s*[\^~]+\s*$")
_LIB_WARNING = re.compile(r"^(/\S+/)(\S+\.py):\d+: (\w+Warning): ")
LIBRARY_FRAMES = "<library frames>"


class Case(Protocol):
    """What the harness reads of a suite's probe case (and, where the suite has them, ``real_may_hang``, a reason,
    and ``real_race``: (a line the real library logs when a race of its own threads hit the run, the reason))."""

    id: str


def reference_time(stdout: str) -> float | None:
    """The probe's origin (absolute sim seconds), from its '#REF' line."""
    return next((float(m.group(1)) for line in stdout.splitlines() if (m := _REF.match(line))), None)


def _is_probe_file(path: str) -> bool:
    return bool(re.search(r"(^|/)p\d\d_[A-Za-z0-9_]+\.py$", path))


def without_library_internals(lines: Sequence[str]) -> Iterator[str]:
    """The lines without the '#REF' line, each run of library frames in a traceback as one LIBRARY_FRAMES line (our
    client library's internals are not the real one's), a library's warning without its path, line and source."""
    i, in_library = 0, False
    while i < len(lines):
        line = lines[i]
        i += 1
        if _REF.match(line):
            continue
        frame = _FRAME.match(line)
        if frame and not _is_probe_file(frame.group(2)):
            # A library frame: skip its source line and caret line too; one marker for a run of them.
            if i < len(lines) and lines[i].startswith(frame.group(1) + "  ") and not _FRAME.match(lines[i]):
                i += 1
                if i < len(lines) and _CARET.match(lines[i]):
                    i += 1
            if not in_library:
                yield f"{frame.group(1)}{LIBRARY_FRAMES}"
            in_library = True
            continue
        in_library = False
        warning = _LIB_WARNING.match(line)
        if warning and not _is_probe_file(warning.group(1) + warning.group(2)):
            line = f"<lib>/{warning.group(2).split('/')[-1]}:<line>: {warning.group(3)}: " + line[warning.end():]
            if i < len(lines) and lines[i].startswith("  "):
                i += 1  # the library source line the warning shows
        yield line


def mask_places(line: str) -> str:
    """The probe's directory and memory addresses masked: they differ between any two runs."""
    return ADDRESS.sub("0xADDR", PROBE_PATH.sub(r"<probe>/\1", line))


def exit_code(result: Any) -> int | None:
    """Exit status as subprocess reports it (negative: killed by that signal); None when the harness killed it."""
    if getattr(result, "exit_signal", None):
        return -result.exit_signal
    return result.exit_code


def describe(side: str, result: Any) -> str:
    """Both streams and how the run ended, for a failure message."""
    ctrl_c = getattr(result, "sigint_s", None)
    return (f"--- {side} stdout ---\n{result.stdout}--- {side} stderr ---\n{result.stderr}"
            f"--- {side} exit {exit_code(result)}; Ctrl+C at {ctrl_c}; {getattr(result, 'notes', '')}\n")


class RealRuns:
    """Runs each probe under the real client library when first needed, and again on request up to ``attempts``
    (real runs are on wall time, so their timing varies); the real side is started once, on the first run."""

    def __init__(self, start: Callable[[], Any], run: Callable[[Any, Any], Any], error: type[Exception],
                 attempts: int, retry_pause_s: float = 0.0) -> None:
        self._start, self._run_probe, self._error = start, run, error
        self.attempts, self.retry_pause_s = attempts, retry_pause_s
        self.side: Any = None
        self.results: dict[str, list] = {}

    def runs(self, case: Case) -> Iterator[Any]:
        """The real runs of ``case`` so far, then one more each time the caller asks, up to ``attempts``."""
        runs = self.results.setdefault(case.id, [])
        for attempt in range(self.attempts):
            if attempt == len(runs):
                if attempt and self.retry_pause_s:
                    time.sleep(self.retry_pause_s)  # a passing slowdown of the machine should not hit every attempt
                runs.append(self._run(case))
            yield runs[attempt]

    def _run(self, case: Case) -> Any:
        try:
            if self.side is None:
                self.side = self._start()
            return self._run_probe(self.side, case)
        except self._error as exc:
            pytest.fail(f"the real side's harness failed for {case.id}: {exc}")

    def close(self) -> None:
        if self.side is not None:
            self.side.close()


class OurRuns:
    """Runs each probe under rosgrade at most once; a failure of our side is that case's failure."""

    def __init__(self, tmp: Path, run: Callable[[Any, Path], Any]) -> None:
        self.tmp, self._run = tmp, run
        self.results: dict[str, object] = {}

    def get(self, case: Case) -> Any:
        if case.id not in self.results:
            try:
                self.results[case.id] = self._run(case, self.tmp / case.id)
            except Exception as exc:  # noqa: BLE001 - reported as this case's failure
                self.results[case.id] = exc
        result = self.results[case.id]
        if isinstance(result, Exception):
            pytest.fail(f"rosgrade could not run {case.id}: {type(result).__name__}: {result}")
        return result


def _unusable(case: Case, result: Any) -> str:
    """Why a real run is no reference either way ('' when it is one): the harness had to kill it in a case whose real
    side may hang, or a race between the real library's own threads hit it (the line it logs then says so)."""
    if getattr(case, "real_may_hang", "") and exit_code(result) is None:
        return f"every real run hung and was killed ({case.real_may_hang})"  # type: ignore[attr-defined]
    line, why = getattr(case, "real_race", ("", ""))
    if line and line in (getattr(result, "stderr", "") or ""):
        return f"every real run was hit by a race of the real library's threads ({why})"
    return ""


def same_as_real(case: Case, real: RealRuns, ours: Any, differences: Callable[[Case, Any, Any], list[str]],
                 library: str) -> None:
    """Pass when ours has no difference from one of the real runs; fail showing the last real run's differences."""
    compared, problems, last, unusable = 0, [], None, ""
    for last in real.runs(case):
        unusable = _unusable(case, last)
        if unusable:
            continue
        compared += 1
        problems = differences(case, last, ours)
        if not problems:
            return
    if not compared:
        pytest.skip(f"{case.id}: {unusable}")
    pytest.fail(f"{case.id}: {len(problems)} difference(s) from real {library} (in each of {real.attempts} real runs; "
                "the last shown):\n" + "\n".join(problems) + "\n\n" + describe("real", last) + describe("ours", ours))


def behaves_as_measured(case: Case, side: str, results: Iterator[Any] | list[Any],
                        check: Callable[[Case, Any], list[str]]) -> None:
    """Pass when one of ``side``'s runs shows the case's measured behaviour (``check`` lists what it lacks)."""
    checked, problems, last, unusable = 0, [], None, ""
    for last in results:
        unusable = _unusable(case, last) if side == "real" else ""
        if unusable:
            continue
        checked += 1
        problems = check(case, last)
        if not problems:
            return
    if not checked:
        pytest.skip(f"{case.id}: {unusable}")
    pytest.fail(f"{case.id} ({side}):\n" + "\n".join(problems) + "\n\n" + describe(side, last))
