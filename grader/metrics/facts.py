"""Facts about a whole run that any criterion's feedback may quote: distance driven, the node's exception, exit."""
from __future__ import annotations

import re

from grader.metrics.base import Measurement
from grader.metrics.motion import path_length
from grader.metrics.run import RunData

# The last line of a Python traceback: "TypeError: shutdown hook [None] must be a function ...".
_EXCEPTION = re.compile(r"^(?:[A-Za-z_][\w]*\.)*[A-Za-z_]\w*(?:Error|Exception|Interrupt|Exit)\b(?::.*)?$")

FACTS = frozenset({"path_length", "exception", "exit_code", "exit_signal", "status", "n_commands", "command_topics",
                   "client_library", "ignored_command_types", "command_type", "int_fields"})
# The smallest normal double: a command component between 0 and this is what rclpy sends for an int written into a
# float64 field (its internal size word read as a double, about 5e-324; grader/runtime/int_fields.py).
_TINY = 2.2250738585072014e-308


def last_exception(run: RunData) -> str:
    """The final line of the last traceback the node printed, or an empty string."""
    seen_traceback = False
    last = ""
    for line in run.lines:
        text = line.text.strip()
        if text.startswith("Traceback (most recent call last)"):
            seen_traceback = True
        elif seen_traceback and _EXCEPTION.match(text):
            last, seen_traceback = text, False
    return last


def run_facts(run: RunData) -> Measurement:
    """Compute the run-wide facts (names in ``FACTS``)."""
    return {
        "path_length": path_length(run.trajectory("ground_truth")),
        "exception": last_exception(run),
        "exit_code": run.run.exit_code,
        "exit_signal": None if run.run.exit_signal is None else str(run.run.exit_signal),
        "status": run.run.status,
        "n_commands": len(run.commands),
        "command_topics": ", ".join(sorted(set(run.commands.topic))),
        "client_library": run.client_library,
        "ignored_command_types": run.ignored_command_types,
        "command_type": run.command_type,
        "int_fields": int_fields(run),
    }


def int_fields(run: RunData) -> str:
    """The command components that carried denormal values ("linear.x, angular.z"), '' when none did."""
    parts = (("linear", run.commands.linear), ("angular", run.commands.angular))
    found = [f"{part}.{axis}" for part, values in parts for i, axis in enumerate("xyz")
             if len(values) and bool(((values[:, i] != 0.0) & (abs(values[:, i]) < _TINY)).any())]
    return ", ".join(found)
