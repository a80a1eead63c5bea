"""The report models: the JSON contract that students, instructors, gradebooks and CI read."""
from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

from grader import __version__

Visibility = Literal["visible", "after_due_date", "hidden"]
TaskStatus = Literal["graded", "error", "timeout", "not_found"]


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


class SubmissionReport(BaseModel):
    """Everything rosgrade found about one submission."""

    rosgrade_version: str = __version__
    submission: str
    score: float = 0.0
    max_score: float = 0.0
    tasks: list[TaskReport] = Field(default_factory=list)

    def total(self) -> SubmissionReport:
        """Return a copy whose score and max_score are the sums over its tasks."""
        return self.model_copy(
            update={
                "score": round(sum(t.score for t in self.tasks), 6),
                "max_score": round(sum(t.max_score for t in self.tasks), 6),
            }
        )
