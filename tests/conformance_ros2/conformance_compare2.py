"""Normalise ROS 2 probe outputs from both sides, summarise what the robot received, and list the differences.

Masked before comparing: the wall stamp of rclpy log lines (``[INFO] [<wall>] [name]: ``), ANSI colours, memory
addresses, the probe script's directory, library frames in tracebacks (one ``<library frames>`` line for a run of
them: our rclpy's internals are not the real one's) and the path and line of a library's warning. Lines that real
ROS 2 prints differently from run to run (a case's `volatile` patterns) are dropped from both sides.
/cmd_vel is compared as a few facts that real ROS 2 shows every run (`summarise_commands`), never as counts of
early messages, which depend on DDS discovery.
"""
from __future__ import annotations

import difflib
import re
from collections.abc import Iterable, Sequence
from typing import Protocol

from tests.conformance_harness import mask_places, without_library_internals

_ANSI = re.compile(r"\x1b\[[0-9;]*m")
_LOG = re.compile(r"^\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[\d+\.\d+\] \[")
GRID_TOLERANCE_S = 0.0101  # one /clock step: the robot stamps a command with the last tick it published


class CommandLike(Protocol):
    t: float
    linear: tuple[float, float, float]
    angular: tuple[float, float, float]


def normalise(text: str, volatile: Sequence[str] = ()) -> list[str]:
    """The lines of one stream with everything that legitimately differs masked, volatile lines dropped."""
    drop = [re.compile(p) for p in volatile]
    out: list[str] = []
    for line in without_library_internals(_ANSI.sub("", text).splitlines()):
        log = _LOG.match(line)
        if log:
            line = f"[{log.group(1)}] [<wall>] [" + line[log.end():]
        line = mask_places(line)
        if not any(p.search(line) for p in drop):
            out.append(line)
    return out


def diff_lines(name: str, expected: Sequence[str], actual: Sequence[str]) -> list[str]:
    """Every line one side has and the other lacks ('real only' / 'ours only'), in order."""
    problems = []
    matcher = difflib.SequenceMatcher(a=list(expected), b=list(actual), autojunk=False)
    for op, a0, a1, b0, b1 in matcher.get_opcodes():
        if op == "equal":
            continue
        problems += [f"{name}: real only:  {line!r}" for line in expected[a0:a1]]
        problems += [f"{name}: ours only:  {line!r}" for line in actual[b0:b1]]
    return problems


def missing_lines(expected: Iterable[str], actual: Sequence[str]) -> list[str]:
    """The expected (normalised) lines that `actual` lacks, looked for in order."""
    missing, pos = [], 0
    for want in expected:
        try:
            pos = list(actual).index(want, pos) + 1
        except ValueError:
            missing.append(want)
    return missing


def _is_zero(c: CommandLike) -> bool:
    return not any(c.linear) and not any(c.angular)


def summarise_commands(commands: Sequence[CommandLike], sigint_s: float | None, markers: bool = False) -> list[str]:
    """What real ROS 2 shows the same way every run: times relative to the origin, SIGINT relative to it too.

    Before Ctrl+C: whether commands arrived, whether all were non-zero and on the 0.1 s grid from the origin (the
    probes' 10 Hz timers start at their origin). After: whether a zero command and whether a non-zero one arrived.
    With `markers`, instead of the timing: the linear.y values that arrived (probes number their publishes there).
    """
    cut = float("inf") if sigint_s is None else sigint_s
    before = [c for c in commands if c.t < cut - 1e-9]
    after = [c for c in commands if c.t >= cut - 1e-9]
    on_grid = all(abs(c.t * 10 - round(c.t * 10)) <= GRID_TOLERANCE_S * 10 for c in before)
    lines = [f"before Ctrl+C: {'commands arrived' if before else 'nothing arrived'}"]
    if before and not markers:
        lines.append(f"before Ctrl+C: all non-zero {not any(_is_zero(c) for c in before)}, "
                     f"on the 0.1 s grid {on_grid}")
    if sigint_s is not None:
        lines.append(f"after Ctrl+C: zero command arrived {any(_is_zero(c) for c in after)}")
        lines.append(f"after Ctrl+C: non-zero command arrived {any(not _is_zero(c) for c in after)}")
    if markers:
        lines.append(f"markers arrived (linear.y) {[c.linear[1] for c in commands]}")
    return lines
