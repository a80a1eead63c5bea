"""Stand-ins for the grading, rubric and recording modules, so CLI tests run without the simulator."""
from __future__ import annotations

import os
import signal
import sys
import time
import types
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np

from grader.report import CriterionResult, RubricStamp, SubmissionReport, TaskReport

CALL_LOG_ENV = "ROSGRADE_TEST_CALL_LOG"
BATCH_PID_ENV = "ROSGRADE_TEST_BATCH_PID"  # who 'interrupt' sends Ctrl+C to: the test's own process
RUBRICS_ENV = "ROSGRADE_TEST_RUBRICS"  # the folder the fake rubrics name as their files (default: rubrics/)
ROOT = Path(__file__).resolve().parents[2]


class SubmissionError(Exception):
    """Fake grader.grading.SubmissionError."""


class RubricError(Exception):
    """Fake grader.rubric.RubricError."""


class RecordingError(Exception):
    """Fake grader.recording.RecordingError."""


def circle_task(radius_ok: bool = True, recordings: list[str] | None = None) -> TaskReport:
    criteria = [
        CriterionResult(
            id="radius", title="Circle radius", score=4.0 if radius_ok else 1.5, max_score=4.0, passed=radius_ok,
            feedback="The circle has the right size." if radius_ok else "Your circle is too big | check ω = v / r.",
            measured={"radius_m": 0.497 if radius_ok else 0.71, "expected_radius_m": 0.5}, scenario="nominal",
        ),
        CriterionResult(
            id="speed_limit", title="Stays within speed limits", score=3.0, max_score=3.0, passed=True,
            feedback="Never faster than 0.26 m/s.", measured={"max_linear_mps": 0.1},
        ),
        CriterionResult(
            id="stops", title="Stops on Ctrl+C", score=0.0, max_score=3.0, passed=False, visibility="hidden",
            feedback="SECRET: the robot kept moving after shutdown.", measured={"drift_m": 0.3},
        ),
    ]
    score = sum(c.score for c in criteria)
    return TaskReport(
        id="move_circle", title="Move in a circle", status="graded", score=score, max_score=10.0,
        criteria=criteria, recordings=recordings or [],
    )


def square_task(status: str = "graded") -> TaskReport:
    if status != "graded":
        return TaskReport(id="move_square", title="Drive a square", status=status, max_score=10.0,
                          message="Traceback: ZeroDivisionError in move_square.py line 12",
                          diagnostics=["move_square.py raised ZeroDivisionError at line 12"])
    criteria = [
        CriterionResult(id="closes", title="Returns to the start", score=5.0, max_score=5.0, passed=True,
                        feedback="Ended 2 cm from the start.", measured={"end_error_m": 0.02}),
        CriterionResult(id="corners", title="Four right-angle corners", score=2.5, max_score=5.0, passed=False,
                        feedback="Two corners were more than 10° off.", measured={"worst_corner_deg": 17.2}),
    ]
    return TaskReport(id="move_square", title="Drive a square", status="graded", score=7.5, max_score=10.0,
                      criteria=criteria)


def make_report(submission: str = "alice", radius_ok: bool = True, square_status: str = "graded",
                recordings: list[str] | None = None) -> SubmissionReport:
    tasks = [circle_task(radius_ok, recordings), square_task(square_status)]
    return SubmissionReport(submission=submission, tasks=tasks).total()


def fake_grade_submission(submission: Path, out_dir: Path, task_ids: Any = None, rubrics: Any = None,
                          jobs: int = 1) -> SubmissionReport:
    """Grades by the submission's name: 'crash' raises, 'bad' is unusable, 'interrupt' sends Ctrl+C to the batch,
    'slow' takes 30 s, 'nap' 0.3 s, 'die' is killed."""
    name = Path(submission).stem
    log = os.environ.get(CALL_LOG_ENV)
    if log:
        with open(log, "a", encoding="utf-8") as handle:
            handle.write(name + "\n")
    if "crash" in name:
        raise RuntimeError("simulated crash in the grader")
    if "bad" in name:
        raise SubmissionError(f"{submission}: no ROS scripts (*.py) found")
    if "interrupt" in name:
        os.kill(int(os.environ.get(BATCH_PID_ENV) or os.getppid()), signal.SIGINT)
        time.sleep(30)
    if "slow" in name:
        time.sleep(30)
    if "nap" in name:  # a little grading time, so a kill can land while jobs are running
        time.sleep(0.3)
    if "die" in name:
        os.kill(os.getpid(), signal.SIGKILL)
    if "noisy" in name:
        print("noise that must not reach --json stdout")
    report = make_report(str(submission), radius_ok="wobbly" not in name)
    if task_ids:
        report = report.model_copy(update={"tasks": [t for t in report.tasks if t.id in task_ids]}).total()
    return report


@dataclass
class FakeGraded:
    """What the fake grade_as_data hands back (the shape of grader.grading.GradedSubmission)."""

    report: SubmissionReport
    files: dict[str, bytes]


def fake_grade_as_data(submission: bytes, label: str, task_ids: Any, rubrics: Any, stage_root: Any = None) -> FakeGraded:
    """Grades like fake_grade_submission (by the submission's name), stamped with the rubric files handed over."""
    report = fake_grade_submission(Path(label), Path("unused"), task_ids)
    files = {f.task_id: f for f in rubrics}
    tasks = [t.model_copy(update={
        "rubric": RubricStamp(file=files[t.id].source, sha256=files[t.id].sha256, scenarios=["nominal"]),
        "recordings": [f"{t.id}/nominal.mcap"] if t.status == "graded" else []}) for t in report.tasks]
    data = {f"{t.id}/nominal.mcap": b"fake mcap of " + submission[:16] for t in tasks if t.recordings}
    return FakeGraded(report.model_copy(update={"tasks": tasks, "recording_format": "fake"}), data)


def grading_module() -> types.ModuleType:
    module = types.ModuleType("grader.grading")
    module.SubmissionError = SubmissionError
    module.grade_submission = fake_grade_submission
    module.grade_as_data = fake_grade_as_data
    return module


def rubric_module() -> types.ModuleType:
    def criterion(cid: str, title: str, points: float, visibility: str = "visible") -> SimpleNamespace:
        return SimpleNamespace(id=cid, title=title, points=points, visibility=visibility)

    def rubric(**fields: Any) -> SimpleNamespace:
        made = SimpleNamespace(**fields)
        made.restricted_to = lambda names: made  # the fake scoring ignores scenarios
        made.scenarios = [SimpleNamespace(name="nominal", model_dump=lambda mode="json": {"name": "nominal"})]
        made.nodes = [SimpleNamespace(script=f"{made.id}.py", aliases=[])]
        for c in made.criteria:
            c.metric = "fake"
        return made

    rubrics = {
        "move_circle": rubric(
            id="move_circle", title="Move in a circle", max_score=10.0, robot="turtlebot3_waffle",
            criteria=[criterion("radius", "Circle radius", 4), criterion("speed_limit", "Stays within speed limits", 3),
                      criterion("stops", "Stops on Ctrl+C", 3, "hidden")],
        ),
        "move_square": rubric(
            id="move_square", title="Drive a square", max_score=10.0, robot="turtlebot3_waffle",
            criteria=[criterion("closes", "Returns to the start", 5), criterion("corners", "Four right-angle corners", 5)],
        ),
    }
    module = types.ModuleType("grader.rubric")
    module.RubricError = RubricError
    def load_rubrics() -> dict[str, Any]:
        for made in rubrics.values():  # read when asked, as the real module reads its folder
            made.source = Path(os.environ.get(RUBRICS_ENV) or ROOT / "rubrics") / f"{made.id}.toml"
        return dict(rubrics)

    def task_table(extra: Any = ()) -> dict[str, Any]:
        for path in extra:
            raise RubricError(f"{path}: the fake rubric module reads no files")
        return load_rubrics()

    def load_rubric(path: Any) -> Any:
        raise RubricError(f"{path}: the fake rubric module reads no files")

    module.load_rubrics = load_rubrics
    module.load_rubric = load_rubric
    module.task_table = task_table
    return module


def series(t: np.ndarray, x: np.ndarray, y: np.ndarray, yaw: np.ndarray) -> SimpleNamespace:
    return SimpleNamespace(t=t, x=x, y=y, yaw=yaw, vx=np.full_like(t, 0.1), wz=np.full_like(t, 0.2))


class FakeRecording:
    """A 0.5 m circle driven at (0.1 m/s, 0.2 rad/s) from (-2, -0.5), with printed poses and a shutdown at 30 s."""

    def __init__(self, path: Path, ground_truth: bool = True, metadata: dict[str, Any] | None = None) -> None:
        self.path = path
        t = np.linspace(0, 35, 351)
        theta = 0.2 * np.minimum(t, 31.4)
        self._odom = series(t, -2.0 + 0.5 * np.sin(theta), -0.5 + 0.5 - 0.5 * np.cos(theta), theta)
        self._truth = ground_truth
        self.metadata = metadata if metadata is not None else {
            "rosgrade": {"robot": "turtlebot3_waffle", "scenario": '{"name": "nominal"}'},
            "rosgrade.run": {"shutdown_requested_s": "30.0", "exit_code": "0"},
        }

    def odometry(self) -> SimpleNamespace:
        return self._odom

    def ground_truth(self) -> SimpleNamespace | None:
        return self._odom if self._truth else None

    def commands(self) -> SimpleNamespace:
        t = np.arange(0, 30, 0.1)
        linear = np.zeros((len(t), 3))
        angular = np.zeros((len(t), 3))
        linear[:, 0], angular[:, 2] = 0.1, 0.2
        return SimpleNamespace(t=t, linear=linear, angular=angular, origin=None)

    def output_lines(self) -> list[tuple[float, str, str]]:
        return [(float(s), "stdout", f"x={self._odom.x[s * 10]:.2f} [m], y={self._odom.y[s * 10]:.2f} [m], yaw=1.0")
                for s in range(0, 30, 3)]


def recording_module() -> types.ModuleType:
    module = types.ModuleType("grader.recording")
    module.RecordingError = RecordingError

    class Recording:
        @staticmethod
        def open(path: Path) -> FakeRecording:
            path = Path(path)
            if not path.exists() or path.read_bytes().startswith(b"garbage"):
                raise RecordingError(f"{path}: not an MCAP or bag file")
            if path.suffix == ".bag":
                return FakeRecording(path, ground_truth=False, metadata={})
            return FakeRecording(path)

    module.Recording = Recording
    return module


def scoring_module() -> types.ModuleType:
    module = types.ModuleType("grader.scoring")
    module.ScoringError = type("ScoringError", (Exception,), {})

    def score_task(rubric: Any, recordings: dict[str, Any]) -> TaskReport:
        task = circle_task()
        return task.model_copy(update={"diagnostics": [f"scenarios: {', '.join(sorted(recordings))}"]})

    module.score_task = score_task
    return module


def install(monkeypatch: Any, name: str, module: types.ModuleType) -> None:
    monkeypatch.setitem(sys.modules, name, module)
