"""Course worlds: named arenas as data that a scenario refers to, built and seen as the scenario's own obstacles."""
from __future__ import annotations

import math

import pytest
from pydantic import ValidationError

from sim import Scenario, World
from sim.course import CourseWorldError, course_worlds, load_course_world
from sim.samples import ScanSample


def test_the_course_worlds_load_with_their_starts() -> None:
    assert {"turtlebot3_world", "arena", "corridor"} <= set(course_worlds())
    tb3 = load_course_world("turtlebot3_world")
    pillars = [p for p in tb3.pillars if p.radius == 0.15]
    assert sorted((p.x, p.y) for p in pillars) == sorted((x, y) for x in (-1.1, 0.0, 1.1) for y in (-1.1, 0.0, 1.1))
    assert (tb3.starts["default"].x, tb3.starts["default"].y) == (-2.0, -0.5)  # the launch files' spawn pose
    with pytest.raises(CourseWorldError, match="no course world 'mars'"):
        load_course_world("mars")


def test_a_named_start_sets_the_pose_and_the_world_its_obstacles() -> None:
    scenario = Scenario(world="arena", start="south")
    assert (scenario.initial_pose.x, scenario.initial_pose.yaw) == (0.3, math.pi / 2)
    assert len(scenario.all_obstacles) == len(load_course_world("arena").obstacles) and scenario.obstacles == []
    again = Scenario.model_validate_json(scenario.model_dump_json())  # as a recording reads it back
    assert again == scenario and len(again.all_obstacles) == len(scenario.all_obstacles)


@pytest.mark.parametrize(("fields", "message"), [
    ({"world": "mars"}, "no course world 'mars'"),
    ({"world": "arena", "start": "roof"}, "start 'roof' is not a start of arena"),
    ({"start": "south"}, "name the world too"),
    ({"world": "arena", "start": "south", "initial_pose": {"x": 1.0}}, "initial_pose differs from start 'south'"),
    ({"robot": "turtlesim", "world": "arena"}, "turtlesim has no base modes, worlds"),
])
def test_bad_world_references_are_named(fields: dict, message: str) -> None:
    with pytest.raises(ValidationError, match=message):
        Scenario(**fields)


def test_a_scenario_without_a_world_is_recorded_as_before() -> None:
    dumped = Scenario(obstacles=[{"kind": "cylinder", "x": 1.0, "y": 0.0, "radius": 0.1}]).model_dump()
    assert "world" not in dumped and "start" not in dumped


def test_the_scan_sees_the_turtlebot3_world_hexagon() -> None:
    world = World(Scenario(world="turtlebot3_world", start="default", duration=1.0))
    scans = [s for s in world.advance_to(world.start_ns + 400_000_000) if isinstance(s, ScanSample)]
    behind = scans[-1].ranges[180]
    # from the scanner (0.064 m behind x = -2.0, y -0.5) straight back to the west-south-west inner wall face, the
    # line from the corner (-2.933, 0) to (-1.466, -2.54): x = -2.644 at y = -0.5
    assert behind == pytest.approx(-2.064 + 2.644, abs=0.01)
