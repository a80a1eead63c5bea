"""The "Measured" column in words a student understands: the few quantities that matter for a criterion, with units.

Metrics report many named quantities (a criterion's own quantity first, see grader/scoring.py). This module is
data: PHRASES says how a quantity reads, COMPANIONS which others belong next to it. A quantity with no phrase (a new
or an instructor's plugin metric) is shown by its name, so new metrics appear without a change here.
"""
from __future__ import annotations

import math
import re
import string
from collections.abc import Mapping
from dataclasses import dataclass

from grader.reports.text import fmt_number, split_unit

Value = float | int | str | bool | None


@dataclass(frozen=True)
class Phrase:
    """How a quantity reads: a template over measured names, shown only when `when` (a measured name) is true."""

    template: str
    when: str | None = None


PHRASES: dict[str, Phrase] = {
    # circle
    "radius": Phrase("circle radius {radius} m"),
    "cmd_radius": Phrase("your commands give v/ω = {cmd_linear}/{cmd_angular} = {cmd_radius} m"),
    "rms_residual": Phrase("{rms_residual} m off a perfect circle on average"),
    "revolutions": Phrase("{revolutions} laps, {arc_length} m driven"),
    # velocity limits
    "violating_fraction": Phrase("{n_violations} of {n_messages} commands over the limits"),
    "n_violations": Phrase("{n_violations} of {n_messages} commands over the limits"),
    "max_linear": Phrase("fastest linear.x {max_linear} m/s (limit {limit_linear} m/s)"),
    "max_angular": Phrase("fastest angular.z {max_angular} rad/s (limit {limit_angular} rad/s)"),
    "n_nonfinite": Phrase("{n_nonfinite} commands with NaN or infinity", when="n_nonfinite"),
    "n_off_axis": Phrase("{n_off_axis} commands with a non-zero component the robot cannot use", when="n_off_axis"),
    # shutdown
    "rest_time": Phrase("at rest {rest_time} s after Ctrl+C"),
    "zero_command_delay": Phrase("zero command sent {zero_command_delay} s after Ctrl+C"),
    "rest_distance": Phrase("moved {rest_distance} m after Ctrl+C"),
    "exit_delay": Phrase("node exited {exit_delay} s after Ctrl+C"),
    "moving_at_end": Phrase("still moving when the recording ended", when="moving_at_end"),
    # stopping at a position
    "final_x": Phrase("ended at x = {final_x} m"),
    "final_distance": Phrase("ended {final_distance} m from the start"),
    "travelled": Phrase("drove {travelled} m"),
    "rest_at_end_s": Phrase("at rest for the last {rest_at_end_s} s"),
    "stopped_at_s": Phrase("stopped {stopped_at_s} s after the start"),
    # square
    "side_worst_error": Phrase("sides {side_min}–{side_max} m long"),
    "side_mean": Phrase("sides {side_min}–{side_max} m long"),
    "corner_worst_error_deg": Phrase("corners {corner_min_deg}–{corner_max_deg}°"),
    "corner_mean_deg": Phrase("corners {corner_min_deg}–{corner_max_deg}°"),
    "closure_worst": Phrase("a loop ended {closure_worst} m from where it began"),
    "closure_first": Phrase("the first loop ended {closure_first} m from where it began"),
    "loops": Phrase("{loops} loops"),
    "loops_at_rest": Phrase("stopped after {loops_at_rest} loops"),
    "final_rest_s": Phrase("at rest for the last {final_rest_s} s"),
    "n_sides": Phrase("{n_sides} sides, {n_corners} corners"),
    "pauses": Phrase("{pauses} pauses", when="pauses"),
    "shape_error": Phrase("sides {side_min}–{side_max} m long, corners {corner_min_deg}–{corner_max_deg}°"),
    "side_first": Phrase("first side {side_first} m long"),
    # loops (figure of eight)
    "n_loops": Phrase("{n_loops} loops ({n_anticlockwise} anticlockwise, {n_clockwise} clockwise)"),
    "order_fraction": Phrase("loops driven in the order {order}; expected {expected_order}"),
    "order_correct": Phrase("loops driven in the order {order}; expected {expected_order}"),
    "diameter_worst_error": Phrase("loop diameters {diameter_min}–{diameter_max} m"),
    "diameter_mean": Phrase("loop diameters {diameter_min}–{diameter_max} m"),
    "loops_s": Phrase("loops took {loops_s} s"),
    # timing
    "motion_s": Phrase("moved for {motion_s} s"),
    "first_motion_s": Phrase("started moving {first_motion_s} s after the start"),
    "rest_at_s": Phrase("came to rest {rest_at_s} s after the start"),
    # final pose
    "start_distance": Phrase("ended {start_distance} m from the start"),
    "line_distance": Phrase("ended {line_distance} m from the start line"),
    "heading_error_deg": Phrase("heading {heading_error_deg}° off the start heading"),
    # log lines
    "format_fraction": Phrase("{n_format_ok} of {n_lines} log lines in the asked format"),
    "values_fraction": Phrase("{n_values_ok} of {n_lines} logged poses correct"),
    "level_fraction": Phrase("log levels used: {levels}"),
    # printed pose
    "fraction_correct": Phrase("{n_correct} of {n_lines} printed poses correct"),
    "n_correct": Phrase("{n_correct} of {n_lines} printed poses correct"),
    "position_error_max": Phrase("largest position error {position_error_max} m"),
    "yaw_error_max_deg": Phrase("largest yaw error {yaw_error_max_deg}° (yaw in {yaw_unit})"),
    "rate_hz": Phrase("printed {rate_hz} times a second"),
    "max_gap_s": Phrase("longest gap between prints {max_gap_s} s"),
    "first_line_s": Phrase("first print {first_line_s} s after the start"),
    # run facts
    "path_length": Phrase("drove {path_length} m"),
    "n_commands": Phrase("{n_commands} velocity commands on {command_topics}"),
    "command_rate_hz": Phrase("{command_rate_hz} velocity commands a second"),
    "format_example": Phrase("e.g. “{format_example}”"),
}

COMPANIONS: dict[str, tuple[str, ...]] = {
    "radius": ("cmd_radius", "revolutions"),
    "revolutions": ("radius", "arc_length"),
    "violating_fraction": ("max_linear", "max_angular", "n_nonfinite", "n_off_axis"),
    "n_violations": ("max_linear", "max_angular", "n_nonfinite", "n_off_axis"),
    "rest_time": ("zero_command_delay", "rest_distance", "moving_at_end"),
    "zero_command_delay": ("rest_time", "exit_delay"),
    "exit_delay": ("zero_command_delay",),
    "final_x": ("final_distance", "moving_at_end"),
    "final_distance": ("final_x", "moving_at_end"),
    "rest_at_end_s": ("final_x", "moving_at_end"),
    "side_worst_error": ("n_sides",),
    "corner_worst_error_deg": ("n_sides",),
    "loops": ("final_rest_s", "pauses"),
    "loops_at_rest": ("final_rest_s",),
    "fraction_correct": ("position_error_max", "yaw_error_max_deg"),
    "rate_hz": ("max_gap_s",),
    "shape_error": ("n_sides",),
    "n_loops": ("order_correct", "diameter_worst_error"),
    "order_fraction": ("n_loops",),
    "order_correct": ("n_loops",),
    "diameter_worst_error": ("n_loops",),
    "motion_s": ("first_motion_s", "rest_at_s"),
    "start_distance": ("heading_error_deg",),
    "line_distance": ("start_distance",),
    "format_fraction": ("format_example",),
    "values_fraction": ("position_error_max", "yaw_error_max_deg"),
    "format_example": (),
}
DEFAULT_LIMIT = 3
_FIELDS = string.Formatter()
_SAME_RANGE = re.compile(r"(?<![\d.])(-?[\d.]+)–\1(?![\d.])")


def _missing(value: Value) -> bool:
    return value is None or (isinstance(value, float) and not math.isfinite(value)) or value == ""


def phrase(name: str, measured: Mapping[str, Value]) -> str:
    """One quantity in words, or '' when it (or a value its phrase needs) was not measured."""
    spec = PHRASES.get(name)
    if spec is None:
        if _missing(measured.get(name)):
            return ""
        label, unit = split_unit(name)
        return f"{label} {fmt_number(measured[name])}{unit}"
    if spec.when is not None and not measured.get(spec.when):
        return ""
    names = [field for _, field, _, _ in _FIELDS.parse(spec.template) if field]
    if any(_missing(measured.get(n)) for n in names):
        return ""
    text = spec.template.format(**{n: fmt_number(measured[n]) for n in names})
    return _SAME_RANGE.sub(r"\1", text)  # "1.02–1.02 m" reads "1.02 m"


def describe(measured: Mapping[str, Value], limit: int | None = DEFAULT_LIMIT) -> str:
    """The criterion's own quantity (the first measured) and its companions, as '; '-separated phrases."""
    if not measured:
        return ""
    own = next(iter(measured))
    parts: list[str] = []
    for name in (own, *COMPANIONS.get(own, ())):
        text = phrase(name, measured)
        if text and text not in parts:
            parts.append(text)
    return "; ".join(parts[:limit])
