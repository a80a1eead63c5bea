"""Collisions: the robot touching walls and pillars, as the world's physics recorded them (``RunData.contacts``)."""
from __future__ import annotations

import math

from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricParams
from grader.metrics.run import Contact, RunData


class Params(MetricParams):
    """When two touches of the same obstacle count as one."""

    # The world checks contacts every 20 ms: a touch that lasts is one sample per check, so a longer gap is a new one.
    gap_s: float = Field(0.05, gt=0)


def touches(contacts: tuple[Contact, ...], gap_s: float) -> list[Contact]:
    """The first contact of each touch: an obstacle touched again after more than ``gap_s`` without contact is
    touched anew."""
    last: dict[str, float] = {}
    first = []
    for contact in contacts:
        if contact.t - last.get(contact.obstacle, -math.inf) > gap_s:
            first.append(contact)
        last[contact.obstacle] = contact.t
    return first


def measure(run: RunData, params: Params) -> Measurement:
    """How many times the robot touched an obstacle, and when, where and what it touched first."""
    hits = touches(run.contacts, params.gap_s)
    first = hits[0] if hits else None
    return {
        "n_collisions": len(hits),
        "collided": bool(hits),
        "first_hit_s": first.t - run.start_time if first else math.nan,
        "first_hit_x": first.x if first else math.nan,
        "first_hit_y": first.y if first else math.nan,
        "first_obstacle": first.obstacle if first else "",
        "obstacles_touched": ", ".join(sorted({hit.obstacle for hit in hits})),
    }


METRIC = Metric(
    name="collisions",
    params=Params,
    quantities=frozenset({"n_collisions", "collided", "first_hit_s", "first_hit_x", "first_hit_y", "first_obstacle",
                          "obstacles_touched"}),
    measure=measure,
)
