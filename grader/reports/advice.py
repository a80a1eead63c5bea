"""Advice read from a task's first recording that no criterion scores but a student should hear: a loop without
`rate.sleep()` that floods the robot with commands gets full marks in simulation and still needs fixing."""
from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from grader.report import SubmissionReport, TaskReport

# A rospy.Rate loop in the course runs at 10-50 Hz; a loop that never sleeps publishes as fast as it can.
FLOOD_HZ = 100.0
_GRADER_ORIGINS = {"world", "grader"}


def command_rate_note(commands: Any, shutdown_s: float | None) -> str | None:
    """The advice for a node that published velocity commands faster than FLOOD_HZ before Ctrl+C, else None."""
    t = np.asarray(commands.t, dtype=float)
    keep = np.ones(len(t), dtype=bool)
    if commands.origin is not None:  # the scripted driver's and the world's commands are not the student's
        keep &= np.array([o not in _GRADER_ORIGINS for o in commands.origin], dtype=bool)
    if shutdown_s is not None:
        keep &= t <= shutdown_s
    t = t[keep]
    if len(t) < 2 or t[-1] <= t[0]:
        return None
    rate = (len(t) - 1) / float(t[-1] - t[0])
    if rate <= FLOOD_HZ:
        return None
    return (f"Your node published {len(t)} velocity commands in {t[-1] - t[0]:.0f} s, about {rate:.0f} a second. "
            "A loop without rate.sleep() runs as fast as the computer can: on a real robot it uses a whole CPU core "
            "and floods the network, while the base only acts on a few commands a second. Create "
            "rate = rospy.Rate(10) before the loop and call rate.sleep() at the end of each pass.")


def with_advice(report: SubmissionReport) -> SubmissionReport:
    """The report with each task's advice appended to its notes (what rosgrade noticed)."""
    tasks = [_advised(task) for task in report.tasks]
    return report.model_copy(update={"tasks": tasks})


def _advised(task: TaskReport) -> TaskReport:
    if not task.recordings:
        return task
    from grader.recording import Recording, RecordingError
    from grader.reports.plots import shutdown_s

    try:
        recording = Recording.open(Path(task.recordings[0]))
        note = command_rate_note(recording.commands(), shutdown_s(recording.metadata or {}))
    except RecordingError:  # the plots say that the recording could not be read
        return task
    if note is None or note in task.diagnostics:
        return task
    return task.model_copy(update={"diagnostics": [*task.diagnostics, note]})
