"""Score recordings against a rubric: a pure, deterministic function of the recordings and the rubric."""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from grader.metrics import Measurement, MetricError, RunData
from grader.metrics.facts import run_facts
from grader.report import CriterionResult, TaskReport
from grader.rubric import Criterion, Hint, Rubric, Scenario, render
from grader.tolerance import tolerance

PASS_CREDIT = 1.0 - 1e-9


class ScoringError(Exception):
    """A recording could not be turned into a run to score."""


@dataclass(frozen=True)
class Outcome:
    """One criterion on one scenario: credit in [0, 1], what was measured and the feedback for it."""

    scenario: str
    credit: float
    measured: Measurement
    feedback: str


def score_task(rubric: Rubric, recordings: Mapping[str, Any]) -> TaskReport:
    """Score every criterion of ``rubric`` on the recordings (``Recording`` or ``RunData``) keyed by scenario name.

    A criterion on several scenarios takes its credit from them as the rubric says: ``min`` (the default; the node
    must work in every scenario) or ``mean``. Its feedback and measured values come from the worst scenario.
    """
    runs = {s.name: _run(recordings[s.name], s) for s in rubric.scenarios if s.name in recordings}
    facts = {name: run_facts(run) for name, run in runs.items()}
    results = [_criterion(rubric, c, runs, facts) for c in rubric.criteria]
    return TaskReport(
        id=rubric.id,
        title=rubric.title,
        status="graded",
        score=round(sum(r.score for r in results), 6),
        max_score=rubric.max_score,
        criteria=results,
        recordings=[str(p) for name in runs if (p := getattr(recordings[name], "path", None)) is not None],
        diagnostics=_diagnostics(rubric, runs),
    )


def _run(recording: Any, scenario: Scenario) -> RunData:
    if isinstance(recording, RunData):
        return recording
    try:
        return RunData.from_recording(recording, scenario.start_time, scenario.shutdown_at)
    except (AttributeError, TypeError, ValueError) as e:
        raise ScoringError(f"scenario {scenario.name!r}: the recording cannot be read as a run: {e}") from e


def _diagnostics(rubric: Rubric, runs: Mapping[str, RunData]) -> list[str]:
    """What the instructor should know about the scoring itself: missing runs, missing ground truth."""
    notes = []
    for s in rubric.scenarios:
        run = runs.get(s.name)
        if run is None:
            notes.append(f"scenario {s.name!r} was not recorded; its criteria score 0")
            continue
        wants_truth = any(
            getattr(c.metric_params, "source", None) == "ground_truth" for c in rubric.criteria if s in rubric.scenario_list(c)
        )
        if wants_truth and run.ground_truth is None:
            notes.append(f"scenario {s.name!r}: the recording has no ground truth, so it was scored from odometry")
    return notes


def _criterion(
    rubric: Rubric, criterion: Criterion, runs: Mapping[str, RunData], facts: Mapping[str, Measurement]
) -> CriterionResult:
    """Evaluate one criterion on each of its scenarios and combine the credit."""
    scenarios = rubric.scenario_list(criterion)
    outcomes = [
        _evaluate(criterion, s, runs[s.name], facts[s.name]) if s.name in runs else _missing(criterion, s)
        for s in scenarios
    ]
    worst = min(outcomes, key=lambda o: o.credit)  # first in rubric order on ties: deterministic
    credits = [o.credit for o in outcomes]
    credit = min(credits) if criterion.combine == "min" else sum(credits) / len(credits)
    feedback = worst.feedback
    if len(set(credits)) > 1:  # only some scenarios went wrong: say which one the feedback is about
        s = next(s for s in scenarios if s.name == worst.scenario)
        about = f" ({s.description})" if s.description else ""
        feedback = f"In scenario '{s.name}'{about}: {feedback}"
    return CriterionResult(
        id=criterion.id,
        title=criterion.title,
        score=round(criterion.points * credit, 4),
        max_score=criterion.points,
        passed=credit >= PASS_CREDIT,
        visibility=criterion.visibility,
        feedback=feedback,
        # The criterion's own quantity first: short views (the console table) show only that one.
        measured={k: _json_value(v) for k, v in sorted(worst.measured.items(), key=lambda kv: kv[0] != criterion.quantity)},
        scenario=worst.scenario,
    )


def _missing(criterion: Criterion, scenario: Scenario) -> Outcome:
    return Outcome(
        scenario.name, 0.0, {},
        f"Scenario '{scenario.name}' has no recording (the run did not complete), so '{criterion.title}' scores 0.",
    )


def _evaluate(criterion: Criterion, scenario: Scenario, run: RunData, facts: Measurement) -> Outcome:
    """Measure, map to credit with the tolerance, and write the feedback with any hints that apply."""
    metric = criterion.metric_def
    lo, hi = criterion.tolerance.bounds
    base = {**facts, "lower": lo, "upper": hi, "expected": criterion.expected_text, "scenario": scenario.name,
            "points": criterion.points}
    try:
        measured = metric.judge(run, criterion.params_for(scenario))
    except MetricError as e:
        values = {**base, "credit": 0.0, "score": 0.0, "measured": None}
        return Outcome(scenario.name, 0.0, {}, _join([f"Could not measure this: {e}.", *_hints(criterion, values)]))
    value = measured[criterion.quantity]
    scored = [(criterion.quantity, criterion.tolerance), *((p.quantity, p.tolerance) for p in criterion.parts)]
    credit = sum(
        tolerance(_number(measured[q]), t.bounds, t.margin, t.sigmoid, t.value_at_margin) for q, t in scored
    ) / len(scored)
    values = {**base, **measured, "measured": value, "credit": credit, "score": credit * criterion.points}
    fb = criterion.feedback
    instead = [render(h.text, values) for h in criterion.hints if h.instead and _applies(h, values)]
    if instead:
        texts = instead
    elif credit >= PASS_CREDIT:
        texts = [render(fb.passed, values)]
    else:
        texts = [render(fb.partial if credit > 0.0 and fb.partial else fb.failed, values), *_hints(criterion, values)]
    return Outcome(scenario.name, credit, measured, _join(texts))


def _applies(hint: Hint, values: Mapping[str, Any]) -> bool:
    return all(c.holds(dict(values)) for c in hint.when)


def _hints(criterion: Criterion, values: Mapping[str, Any]) -> list[str]:
    return [render(h.text, dict(values)) for h in criterion.hints if not h.instead and _applies(h, values)]


def _join(texts: list[str]) -> str:
    return " ".join(t.strip() for t in texts if t.strip())


def _number(value: Any) -> float | None:
    """The measured value as a number for the tolerance: booleans count as 1/0, text as missing."""
    if value is None or isinstance(value, str):
        return None
    return float(value)


def _json_value(value: Any) -> float | int | str | bool | None:
    """NaN and infinity have no JSON form: report them as null."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value
