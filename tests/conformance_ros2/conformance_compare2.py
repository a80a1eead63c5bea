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

_ANSI = re.compile(r"\x1b\[[0-9;]*m")
_LOG = re.compile(r"^\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[\d+\.\d+\] \[")
_PROBE_PATH = re.compile(r"(?:[^\s'\"():,]*/)?(p\d\d_[A-Za-z0-9_]+\.py)")
_ADDR = re.compile(r"0x[0-9a-fA-F]{6,}")
_REF = re.compile(r"^#REF (-?\d+\.\d+)\s*$")
_FRAME = re.compile(r'^(\s*)File "([^"]+)", line \d+, in (.+)$')
_CARET = re.compile(r"^\s*[\^~]+\s*$")
_LIB_WARNING = re.compile(r"^(/\S+/)(\S+\.py):\d+: (\w+Warning): ")
GRID_TOLERANCE_S = 0.0101  # one /clock step: the robot stamps a command with the last tick it published


class CommandLike(Protocol):
    t: float
    linear: tuple[float, float, float]
    angular: tuple[float, float, float]


def reference_time(stdout: str) -> float | None:
    """The probe's origin (absolute sim seconds), from its '#REF' line."""
    for line in stdout.splitlines():
        m = _REF.match(line)
        if m:
            return float(m.group(1))
    return None


def _is_probe_file(path: str) -> bool:
    return bool(re.search(r"(^|/)p\d\d_[A-Za-z0-9_]+\.py$", path))


def normalise(text: str, volatile: Sequence[str] = ()) -> list[str]:
    """The lines of one stream with everything that legitimately differs masked, volatile lines dropped."""
    drop = [re.compile(p) for p in volatile]
    out: list[str] = []
    lines = _ANSI.sub("", text).splitlines()
    i = 0
    in_library = False
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
                out.append(f"{frame.group(1)}<library frames>")
            in_library = True
            continue
        in_library = False
        warning = _LIB_WARNING.match(line)
        if warning and not _is_probe_file(warning.group(1) + warning.group(2)):
            line = f"<lib>/{warning.group(2).split('/')[-1]}:<line>: {warning.group(3)}: " + line[warning.end():]
            if i < len(lines) and lines[i].startswith("  "):
                i += 1  # the library source line the warning shows
        log = _LOG.match(line)
        if log:
            line = f"[{log.group(1)}] [<wall>] [" + line[log.end():]
        line = _PROBE_PATH.sub(r"<probe>/\1", line)
        line = _ADDR.sub("0xADDR", line)
        if any(p.search(line) for p in drop):
            continue
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
