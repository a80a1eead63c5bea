"""The report models: the JSON contract that students, instructors, gradebooks and CI read."""
from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

from grader import __version__

Visibility = Literal["visible", "after_due_date", "hidden"]
TaskStatus = Literal["graded", "error", "timeout", "not_found"]
# What the recordings are: a change here (another profile, encoding or layout) makes old recordings unusable.
RECORDING_FORMAT = "mcap ros1 rosgrade-1"


class CriterionResult(BaseModel):
    """One rubric criterion as scored: points, whether it passed, and feedback a beginner can act on."""

    id: str
    title: str
    score: float
    max_score: float
    passed: bool
    visibility: Visibility = "visible"
    feedback: str = ""
    measured: dict[str, float | int | str | bool | None] = Field(default_factory=dict)
    scenario: str | None = None


class RubricStamp(BaseModel):
    """Which rubric made a task's scores: the file it came from, a hash of its content, the scenarios it ran."""

    file: str
    sha256: str
    scenarios: list[str] = Field(default_factory=list)


class TaskReport(BaseModel):
    """One task of a submission: its status, its criteria, and where its recordings are."""

    id: str
    title: str = ""
    status: TaskStatus
    score: float = 0.0
    max_score: float = 0.0
    criteria: list[CriterionResult] = Field(default_factory=list)
    recordings: list[str] = Field(default_factory=list)
    diagnostics: list[str] = Field(default_factory=list)
    message: str = ""
    rubric: RubricStamp | None = None  # None in reports made before rosgrade recorded it


class SubmissionReport(BaseModel):
    """Everything rosgrade found about one submission."""

    rosgrade_version: str = __version__
    recording_format: str | None = None  # RECORDING_FORMAT when rosgrade made the recordings
    submission: str
    score: float = 0.0
    max_score: float = 0.0
    tasks: list[TaskReport] = Field(default_factory=list)
    # How the student's nodes were confined (e.g. "bubblewrap with a per-node uid", "rlimits only (no isolation)").
    isolation: str = ""

    def total(self) -> SubmissionReport:
        """Return a copy whose score and max_score are the sums over its tasks."""
        return self.model_copy(
            update={
                "score": round(sum(t.score for t in self.tasks), 6),
                "max_score": round(sum(t.max_score for t in self.tasks), 6),
            }
        )
