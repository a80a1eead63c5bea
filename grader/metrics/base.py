"""What every metric shares: its error, its parameter base class and the registry entry that describes it."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Literal

from pydantic import BaseModel, ConfigDict

from grader.metrics.run import RunData

Value = float | int | str | bool | None
Measurement = dict[str, Value]
# What every metric but the shutdown ones reports besides its own quantities: until when it judged the run.
JUDGED = frozenset({"judged_until_s", "judged_until_ctrl_c"})


class MetricError(Exception):
    """The recording holds too little to measure this (say, the robot never moved); the message is for a student."""


class MetricParams(BaseModel):
    """Parameters of a metric as a rubric gives them; unknown names are an error, so typos surface at load time."""

    model_config = ConfigDict(extra="forbid", frozen=True)


class TrajectoryParams(MetricParams):
    """Parameters of a metric that reads the robot's path: which path, and what counts as standing still."""

    # ground_truth: where the robot really went; odometry: what the node could see (its closed-loop reference).
    source: Literal["ground_truth", "odometry"] = "ground_truth"
    rest_speed: float = 0.01  # m/s below which the robot counts as standing still
    rest_turn_rate: float = 0.05  # rad/s, likewise for turning on the spot


@dataclass(frozen=True)
class Metric:
    """A registered metric: its name in rubrics, its parameters, the quantities it reports and how to measure them."""

    name: str
    params: type[MetricParams]
    quantities: frozenset[str]
    measure: Callable[[RunData, MetricParams], Measurement]
    needs_shutdown: bool = False  # only meaningful on scenarios that send Ctrl+C

    @property
    def reported(self) -> frozenset[str]:
        """Every quantity a measurement holds: the metric's own and, unless it judges the shutdown, ``JUDGED``."""
        return self.quantities if self.needs_shutdown else self.quantities | JUDGED

    def judge(self, run: RunData, params: MetricParams) -> Measurement:
        """Measure what the criterion judges: the run until Ctrl+C (the shutdown metrics: all of it), saying until
        when in ``judged_until_s`` (seconds after the start) and ``judged_until_ctrl_c``."""
        if self.needs_shutdown:
            return self.measure(run, params)
        judged = run.until_ctrl_c()
        ctrl_c = run.shutdown_time()
        ends = [float(p.t[-1]) for p in (judged.odometry, judged.ground_truth) if p is not None and len(p)]
        until = ctrl_c if ctrl_c is not None else max(ends, default=run.start_time)
        return {**self.measure(judged, params), "judged_until_s": until - run.start_time,
                "judged_until_ctrl_c": ctrl_c is not None}
