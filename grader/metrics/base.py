"""What every metric shares: its error, its parameter base class and the registry entry that describes it."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Literal

from pydantic import BaseModel, ConfigDict

from grader.metrics.run import RunData

Value = float | int | str | bool | None
Measurement = dict[str, Value]


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
