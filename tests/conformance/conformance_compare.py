"""Normalise probe outputs from both sides and list their differences.

Masked before comparing: the wall-clock field of rospy log lines, memory addresses (``0x7f..``), anonymous-name
PIDs, the directory of the probe script, and library frames in tracebacks (collapsed to one ``<library frames>``
line, since our client library's internals are not the real one's). Sim times are made relative to the probe's
``#REF`` line (its origin) and compared numerically: ``t=`` values and the sim field of log lines must agree within
one clock step.
"""
from __future__ import annotations

import difflib
import re
from dataclasses import dataclass

from tests.conformance_harness import mask_places, reference_time, without_library_internals

CLOCK_STEP_S = 0.01
TOLERANCE_S = CLOCK_STEP_S + 1e-6

_LOG = re.compile(r"^\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[(\d+\.\d+)(?:, (\d+\.\d+))?\]: ")
_ANON = re.compile(r"_\d{2,7}_\d{13}\b")
_T = re.compile(r"\bt=(-?\d+\.\d+)")


@dataclass(frozen=True)
class Line:
    template: str                # the text with every sim time replaced by 't=*'
    times: tuple[float, ...]     # the sim times, relative to the origin

    def render(self) -> str:
        parts = self.template.split("t=*")
        out = parts[0]
        for value, rest in zip(self.times, parts[1:]):
            out += f"t={value:.3f}" + rest
        return out


def normalise(text: str, ref: float | None) -> list[Line]:
    """Lines of one stream, masked and with sim times made relative to `ref`."""
    out: list[Line] = []
    for line in without_library_internals(text.splitlines()):
        times: list[float] = []
        log = _LOG.match(line)
        if log:
            level, _wall, sim = log.groups()
            if sim is None:
                head = f"[{level}] [<wall>]: "
            elif float(sim) == 0.0:
                head = f"[{level}] [<wall>, 0.000000]: "
            else:
                head = f"[{level}] [<wall>, t=*]: "
                times.append(float(sim) - ref if ref is not None else float(sim))
            line = head + line[log.end():]
        line = _ANON.sub("_<PID>_<MS>", mask_places(line))
        for m in _T.finditer(line):
            times.append(float(m.group(1)))
        out.append(Line(_T.sub("t=*", line), tuple(times)))
    return out


def diff_streams(name: str, expected: str, expected_ref: float | None, actual: str, actual_ref: float | None,
                 tolerance_s: float = CLOCK_STEP_S) -> list[str]:
    """Every difference between two outputs of one stream, as readable lines ('' when they agree)."""
    exp = normalise(expected, expected_ref)
    act = normalise(actual, actual_ref)
    problems: list[str] = []
    matcher = difflib.SequenceMatcher(a=[x.template for x in exp], b=[x.template for x in act], autojunk=False)
    for op, a0, a1, b0, b1 in matcher.get_opcodes():
        if op == "equal":
            for a, b in zip(exp[a0:a1], act[b0:b1]):
                if any(abs(x - y) > tolerance_s + 1e-6 for x, y in zip(a.times, b.times)):
                    problems.append(f"{name}: time differs by more than {tolerance_s:g} s:\n"
                                    f"    real: {a.render()}\n    ours: {b.render()}")
            continue
        for a in exp[a0:a1]:
            problems.append(f"{name}: real only:  {a.render()!r}")
        for b in act[b0:b1]:
            problems.append(f"{name}: ours only:  {b.render()!r}")
    return problems


def diff_commands(expected: list, expected_ref: float | None, actual: list, actual_ref: float | None,
                  tolerance_s: float = CLOCK_STEP_S) -> list[str]:
    """Compare /cmd_vel streams: the same messages (values, in order), at the same times relative to the origin."""
    def rows(cmds, ref):
        return [((c.t - ref) if ref is not None else c.t, tuple(c.linear), tuple(c.angular), c.callerid) for c in cmds]

    exp, act = rows(expected, expected_ref), rows(actual, actual_ref)
    problems = []
    key = lambda r: (r[1], r[2])  # noqa: E731
    matcher = difflib.SequenceMatcher(a=[key(r) for r in exp], b=[key(r) for r in act], autojunk=False)
    for op, a0, a1, b0, b1 in matcher.get_opcodes():
        if op == "equal":
            for a, b in zip(exp[a0:a1], act[b0:b1]):
                if abs(a[0] - b[0]) > tolerance_s + 1e-6:
                    problems.append(f"/cmd_vel: time differs: real t={a[0]:.3f} ours t={b[0]:.3f} for {a[1]}, {a[2]}")
                if a[3] != b[3]:
                    problems.append(f"/cmd_vel: callerid differs: real {a[3]} ours {b[3]}")
            continue
        for a in exp[a0:a1]:
            problems.append(f"/cmd_vel: received in real only: t={a[0]:.3f} linear={a[1]} angular={a[2]}")
        for b in act[b0:b1]:
            problems.append(f"/cmd_vel: received in ours only: t={b[0]:.3f} linear={b[1]} angular={b[2]}")
    return problems


def missing_lines(expected: list[str], text: str, ref: float | None) -> list[str]:
    """The expected lines (already in normalised form, times relative to the origin) that `text` lacks, in order."""
    got = normalise(text, ref)
    missing = []
    pos = 0
    for want_text in expected:
        want = normalise(want_text, 0.0)[0]
        for k in range(pos, len(got)):
            if got[k].template == want.template and all(
                    abs(x - y) <= TOLERANCE_S for x, y in zip(got[k].times, want.times)):
                pos = k + 1
                break
        else:
            missing.append(want_text)
    return missing
