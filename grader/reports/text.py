"""Small text formatters shared by the console table, Markdown, HTML and platform outputs, so they all agree."""
from __future__ import annotations

from grader.metrics.run import TURTLE_POSE_TOPIC
from grader.recording import Recording, RecordingError
from grader.report import CriterionResult, SubmissionReport, TaskReport

# Measured names end in their unit (radius_m, max_linear_mps); shown as "radius 0.497 m".
UNIT_SUFFIXES = {"_mps": "m/s", "_radps": "rad/s", "_deg": "°", "_rad": "rad", "_hz": "Hz", "_pct": "%", "_m": "m", "_s": "s"}

NOTICED_HEADING = "What rosgrade noticed while running your node"

# "error": nothing could run (a launch file refused, a link out of the submission, a type the task needs) or the
# grader could not finish a run; a node that crashes is graded (its criteria say what it did).
_STATUS_TEXT = {
    "error": "This task could not be graded:",
    "timeout": "Your node did not finish within the time limit.",
    "not_found": "No script for this task was found in your submission.",
}


def fmt_number(value: float | int | str | bool | None) -> str:
    """A measured value in a short, readable form (0.4971 → 0.497, True → yes)."""
    if value is None:
        return "–"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if value == 0 or 1e-3 <= abs(value) < 1e6:
            return f"{value:.3f}".rstrip("0").rstrip(".") or "0"
        return f"{value:.3g}"
    return str(value)


def fmt_score(value: float) -> str:
    """Points rounded for people: one decimal (15.297 → 15.3), two when one would hide a small amount (0.04)."""
    for digits in (1, 2):
        text = f"{value:.{digits}f}"
        if float(text) != 0 or value == 0:
            break
    return text.rstrip("0").rstrip(".") if "." in text else text


def fmt_points(score: float, max_score: float) -> str:
    """Points as 'score / max', rounded for people."""
    return f"{fmt_score(float(score))} / {fmt_score(float(max_score))}"


def split_unit(name: str) -> tuple[str, str]:
    """A measured name as (readable label, ' unit'), e.g. 'max_linear_mps' → ('max linear', ' m/s')."""
    for suffix, unit in UNIT_SUFFIXES.items():
        if name.endswith(suffix) and len(name) > len(suffix):
            return name[: -len(suffix)].replace("_", " "), ("" if unit == "°" else " ") + unit
    return name.replace("_", " "), ""


def is_public(criterion: CriterionResult) -> bool:
    """Whether a student may see this criterion's feedback and measurements now."""
    return criterion.visibility == "visible"


def task_status_text(task: TaskReport) -> str:
    """One beginner-friendly line on why a task was not graded normally ('' when it was)."""
    if task.status == "graded":
        return ""
    base = _STATUS_TEXT[task.status]
    return f"{base} {task.message}".strip()


def percent(report: SubmissionReport) -> float:
    """The submission's score in percent (0 when nothing could be scored)."""
    return 100.0 * report.score / report.max_score if report.max_score > 0 else 0.0


def foxglove_help(recording: str) -> list[str]:
    """How to look at a recording in Foxglove, step by step, with plot paths of the world the run had."""
    return [
        f"Open a recording in Foxglove: go to https://app.foxglove.dev (or the desktop app) → "
        f"Open local file → {recording}",
        _plot_help(recording),
    ]


def _plot_help(recording: str) -> str:
    """The Plot panel's paths: turtle1's pose in a turtlesim recording (it has no /odom), else the robot's odometry."""
    try:
        topics = {info.topic for info in Recording.open(recording).topics()}
    except RecordingError:
        topics = set()
    if TURTLE_POSE_TOPIC in topics:
        return (f"Add a Plot panel with paths such as {TURTLE_POSE_TOPIC}.x, {TURTLE_POSE_TOPIC}.y and "
                "/turtle1/cmd_vel.linear.x; the report's turtlesim picture shows what the pens drew, and a Raw "
                "Messages panel on /rosout shows your node's log.")
    return ("Add a Plot panel with paths such as /odom.pose.pose.position.x, /odom.pose.pose.position.y "
            "and /cmd_vel.linear.x (/cmd_vel.twist.linear.x for a ROS 2 TwistStamped); a Raw Messages panel on /rosout "
            "shows your node's log.")


def watch_first(report: SubmissionReport) -> tuple[TaskReport, str] | None:
    """The run to watch first in the report's replays: the scenario whose criteria lost the most points (the first
    one in report order on a tie, the first run of a full-marks report)."""
    runs = [(task, scenario) for task in report.tasks for scenario in _scenarios(task)]
    if not runs:
        return None

    def lost(run: tuple[TaskReport, str]) -> float:
        return sum(c.max_score - c.score for c in run[0].criteria if c.scenario == run[1])

    return max(runs, key=lost)


def watch_first_text(report: SubmissionReport) -> str:
    """One line saying which replay in report.html to watch first ('' without recordings)."""
    first = watch_first(report)
    if first is None:
        return ""
    task, scenario = first
    return f"Watch first: the replay of {task.id}, scenario '{scenario}', in report.html."


def replay_elsewhere_text(report: SubmissionReport) -> str:
    """Where a student whose platform shows no files can watch the runs ('' without recordings)."""
    first = watch_first(report)
    if first is None:
        return ""
    task, scenario = first
    return (f"To watch what your robot did, run `rosgrade check` on your package: its report.html replays every run. "
            f"Watch first: {task.id}, scenario '{scenario}'.")


def _scenarios(task: TaskReport) -> list[str]:
    """The task's recorded scenarios, named as its recordings' files are (<scenario>.mcap)."""
    return [recording.replace("\\", "/").rsplit("/", 1)[-1].rsplit(".", 1)[0] for recording in task.recordings]
