"""Exploration (zones of the course world reached, and when) and wall following (MIT RSS's loss and score from the
distance to the followed wall, and the end zone), on synthetic paths through the arena and the corridor."""
from __future__ import annotations

import math
from dataclasses import replace

import pytest
from scoring_synth import run

from grader.metrics.base import MetricError
from grader.metrics.exploration import Params as ExplorationParams
from grader.metrics.exploration import measure as explore
from grader.metrics.wall_following import Params as WallParams
from grader.metrics.wall_following import measure as follow
from grader.metrics.wall_following import wall_distance
from sim.course import load_course_world
from sim.scenario import Box

ARENA = load_course_world("arena").obstacles
CORRIDOR = load_course_world("corridor").obstacles


def _in(obstacles, segments, **start):
    return replace(run(segments, **start), obstacles=obstacles, robot="turtlebot3_waffle")


def test_zones_reached_in_order_with_their_times() -> None:
    # from the centre: 2 m east-north-east at 45°, into north_east (x, y >= 1.5) after about 2.12 m / 0.2 m/s
    m = explore(_in(ARENA, [(15.0, 0.2, 0.0)], yaw0=math.pi / 4), ExplorationParams())
    assert (m["zones_reached"], m["n_zones"]) == (1, 4)
    assert m["zone_times"].startswith("north_east ") and m["zones_missed"] == "north_west, south_west, south_east"
    assert m["last_zone_at_s"] == pytest.approx(1.5 * math.sqrt(2) / 0.2, abs=0.05)
    assert m["zone_fraction"] == 0.25 and m["cells_visited"] >= 5


def test_a_zone_reached_after_until_s_does_not_count() -> None:
    m = explore(_in(ARENA, [(15.0, 0.2, 0.0)], yaw0=math.pi / 4), ExplorationParams(until_s=10.0))
    assert (m["zones_reached"], m["zones_missed"]) == (0, "north_west, north_east, south_west, south_east")


def test_only_the_named_zones_count_and_an_unknown_zone_is_named() -> None:
    m = explore(_in(ARENA, [(15.0, 0.2, 0.0)], yaw0=math.pi / 4), ExplorationParams(zones=["south_west"]))
    assert (m["zones_reached"], m["n_zones"], m["zones_missed"]) == (0, 1, "south_west")
    with pytest.raises(MetricError, match="no zone middle; its zones are north_west"):
        explore(_in(ARENA, [(1.0, 0.2, 0.0)]), ExplorationParams(zones=["middle"]))


def test_no_course_world_no_zones() -> None:
    with pytest.raises(MetricError, match="not in a course world"):
        explore(_in((Box(kind="box", x=2.0, y=0.0, length=0.1, width=1.0),), [(1.0, 0.2, 0.0)]), ExplorationParams())


def test_following_the_corridors_left_wall_at_its_distance_reaches_the_end() -> None:
    # 0.35 m right of the centre line: the left wall's face (y = 0.6) is 0.95 m away, the right one's 0.25 m
    m = follow(_in(CORRIDOR, [(20.0, 0.2, 0.0)], y0=-0.35), WallParams(side="left", desired_distance=0.95))
    assert m["reached_end"] and m["reached_end_at_s"] == pytest.approx(3.0 / 0.2, abs=0.05)
    assert m["mean_distance"] == pytest.approx(0.95, abs=1e-9) and m["loss"] == pytest.approx(0.0, abs=1e-9)
    assert m["mit_score"] == pytest.approx(1.0)


def test_the_loss_is_the_mean_absolute_error_and_the_score_mits() -> None:
    m = follow(_in(CORRIDOR, [(20.0, 0.2, 0.0)], y0=-0.35), WallParams(side="right", desired_distance=0.5,
                                                                          alpha=2.0))
    assert m["mean_distance"] == pytest.approx(0.25, abs=1e-9)
    assert m["loss"] == pytest.approx(0.25, abs=1e-9) and m["mit_score"] == pytest.approx(1 / (2.0 * 0.25 + 1))


def test_a_run_that_stops_short_does_not_reach_the_end() -> None:
    m = follow(_in(CORRIDOR, [(5.0, 0.2, 0.0), (10.0, 0.0, 0.0)]), WallParams(desired_distance=0.6))
    assert not m["reached_end"] and math.isnan(m["reached_end_at_s"])
    assert m["loss"] == pytest.approx(0.0, abs=1e-9) and m["mit_score"] == 0.0  # MIT scores only runs that finish


def test_wall_distance_sees_only_the_followed_side() -> None:
    assert wall_distance(1.0, 0.0, 0.0, +1, CORRIDOR, 2.0) == pytest.approx(0.6)
    assert wall_distance(1.0, 0.2, math.pi, +1, CORRIDOR, 2.0) == pytest.approx(0.8)  # facing back: left is -y
    assert math.isinf(wall_distance(1.0, 0.0, 0.0, +1, CORRIDOR, 0.5))  # beyond reach
