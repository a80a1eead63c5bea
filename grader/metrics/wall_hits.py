"""Wall hits in turtlesim: each update that clamped the turtle to the canvas logs ``Oh no! I hit the wall!``."""
from __future__ import annotations

import math
import re

from grader.metrics.base import Measurement, Metric, MetricParams
from grader.metrics.run import RunData

WARNING = "Oh no! I hit the wall!"
_CLAMP = re.compile(r"Clamping from \[x=(?P<x>[-+\d.e]+), y=(?P<y>[-+\d.e]+)\]")


class Params(MetricParams):
    """No settings: the warning is turtlesim's own."""


def measure(run: RunData, params: Params) -> Measurement:
    """Count the warnings on /rosout; where and when the first one came."""
    hits = [line for line in run.lines if line.stream == "rosout" and WARNING in line.text]
    first = _CLAMP.search(hits[0].text) if hits else None
    return {
        "n_wall_hits": len(hits),
        "hit_wall": bool(hits),
        "first_hit_s": hits[0].t - run.start_time if hits else math.nan,
        # turtlesim reports the screen position (y down) it clamped from, in metres.
        "first_hit_x": float(first.group("x")) if first else math.nan,
        "first_hit_y_screen": float(first.group("y")) if first else math.nan,
    }


METRIC = Metric(
    name="wall_hits",
    params=Params,
    quantities=frozenset({"n_wall_hits", "hit_wall", "first_hit_s", "first_hit_x", "first_hit_y_screen"}),
    measure=measure,
)
