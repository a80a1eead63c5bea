"""Which course world a run took place in, found from its recorded walls and pillars, and that world's zones.

A recording holds its scenario's obstacles (the course world's first, then the scenario's own), not the world's
zones: the zones are read from the course world whose walls and pillars open the recorded list.
"""
from __future__ import annotations

from grader.metrics.base import MetricError
from grader.metrics.run import RunData
from sim.course import CourseWorld, Zone, course_worlds, load_course_world


def course_world(run: RunData) -> CourseWorld:
    """The course world whose walls and pillars the run's obstacles begin with (the one with most, if several)."""
    found = [world for world in map(load_course_world, course_worlds())
             if world.obstacles and run.obstacles[:len(world.obstacles)] == world.obstacles]
    if not found:
        raise MetricError("this run was not in a course world (turtlebot3_world, the arena, the corridor ...), so it "
                          "has no zones to reach")
    return max(found, key=lambda world: len(world.obstacles))


def zones(run: RunData, names: list[str] | None) -> dict[str, Zone]:
    """The named zones of the run's course world (all of them when ``names`` is None), in the world's order."""
    world = course_world(run)
    if names is None:
        return dict(world.zones)
    unknown = [name for name in names if name not in world.zones]
    if unknown:
        raise MetricError(f"the {world.description} has no zone {', '.join(unknown)}; its zones are "
                          f"{', '.join(world.zones) or 'none'}")
    return {name: world.zones[name] for name in names}
