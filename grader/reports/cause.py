"""The real cause first: when a student's node crashed or never ran, every report leads with the exception and where
it happened, instead of criterion feedback about topics and shutdown hooks that only follows from it."""
from __future__ import annotations

import re
from dataclasses import dataclass

from grader.report import CriterionResult, TaskReport
from grader.reports.measured import describe
from grader.reports.text import task_status_text

# The runtime's findings name the exception that ended the node ("... stopped with an uncaught NameError at ...").
_UNCAUGHT = re.compile(r"stopped with an uncaught ([\w.]+)")
# What rospy.sleep / Rate.sleep raise once the node has been shut down (Ctrl+C, a required node ending): the usual
# way a node without try/except ends at Ctrl+C, not a crash that the criteria follow from.
_SHUTDOWN_EXCEPTIONS = {"ROSInterruptException"}
_NEVER_INITIALISED = "never called rospy.init_node()"
# Exceptions raised before the first line runs: the file could not even be compiled.
_COMPILE_ERRORS = {"SyntaxError", "IndentationError", "TabError"}


@dataclass(frozen=True)
class Cause:
    """Why a node's run went wrong: it never ran at all, or it crashed part way."""

    never_ran: bool
    note: str

    @property
    def headline(self) -> str:
        """The one line every report shows first."""
        if self.never_ran:
            return f"Your node never ran, so nothing below could be measured. {self.note}"
        return f"Your node crashed; what it did before that was graded. {self.note}"


def _crash_kind(diagnostic: str) -> str | None:
    """The exception's class name when a finding says it ended the node, unless it is rospy's shutdown exception."""
    found = _UNCAUGHT.search(diagnostic)
    if found is None:
        return None
    kind = found.group(1).rstrip(".").rsplit(".", 1)[-1]
    return None if kind in _SHUTDOWN_EXCEPTIONS else kind


def node_cause(task: TaskReport) -> Cause | None:
    """The crash or start failure among a task's findings, or None when the node ran normally."""
    crash = next((d for d in task.diagnostics if _crash_kind(d)), None)
    if crash is None:
        return None
    kind = _crash_kind(crash)
    never_ran = kind in _COMPILE_ERRORS or any(_NEVER_INITIALISED in d for d in task.diagnostics)
    return Cause(never_ran, crash)


def criterion_feedback(task: TaskReport, criterion: CriterionResult) -> str:
    """The feedback to show for a lost criterion of a node that failed: for one that never ran, that instead of topic
    advice; for one that crashed, the crash first (the criterion's own advice may only follow from it)."""
    cause = node_cause(task)
    if cause is None or criterion.passed:
        return criterion.feedback
    if cause.never_ran:
        return "Not measured: your node never ran (see the error above)."
    return f"Your node had crashed (see the error above); fix that first. {criterion.feedback}".strip()


def criterion_measured(task: TaskReport, criterion: CriterionResult) -> str:
    """The Measured text to show: nothing for a node that never ran (zeros measured from no run mislead)."""
    cause = node_cause(task)
    if cause is not None and cause.never_ran and not criterion.passed:
        return ""
    return describe(criterion.measured)


def noticed(task: TaskReport) -> list[str]:
    """The task's findings, the crash first (it is usually the whole answer)."""
    cause = node_cause(task)
    if cause is None:
        return list(task.diagnostics)
    return [cause.note] + [d for d in task.diagnostics if d != cause.note]


def lead_lines(task: TaskReport) -> list[str]:
    """What a report says about a task before its criteria: the crash, then why it was not graded normally."""
    cause = node_cause(task)
    return [line for line in (cause.headline if cause else "", task_status_text(task)) if line]
