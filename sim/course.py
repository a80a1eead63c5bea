"""Course worlds: named arenas (walls, pillars, start poses, zones) kept as TOML in ``sim/course_worlds/``.

A scenario names one (``world = "turtlebot3_world"``) and picks a start pose by name (``start = "default"``); the
world's walls and pillars come before the scenario's own ``obstacles``. Walls are boxes and pillars cylinders, the
shapes the MuJoCo engine builds and the LiDAR sees.
"""
from __future__ import annotations

import functools
import tomllib
from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from sim.scenario import Box, Cylinder, Pose2D

WORLDS_DIR = Path(__file__).parent / "course_worlds"


class CourseWorldError(Exception):
    """A course world that is missing, unreadable or invalid (the message names the file)."""


class Zone(BaseModel):
    """An axis-aligned rectangle of the floor that a task may ask the robot to reach (metres, world frame)."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)

    x_min: float
    x_max: float
    y_min: float
    y_max: float

    @model_validator(mode="after")
    def _ordered(self) -> Zone:
        if not (self.x_min < self.x_max and self.y_min < self.y_max):
            raise ValueError("a zone needs x_min < x_max and y_min < y_max")
        return self

    def contains(self, x: float, y: float) -> bool:
        return self.x_min <= x <= self.x_max and self.y_min <= y <= self.y_max


class CourseWorld(BaseModel):
    """One course world: where it comes from, its walls and pillars, its start poses and zones by name."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)

    name: str
    description: str
    source: str = Field(description="where the geometry was read from")
    walls: list[Box] = Field(default_factory=list)
    pillars: list[Cylinder] = Field(default_factory=list)
    starts: dict[str, Pose2D] = Field(min_length=1)
    zones: dict[str, Zone] = Field(default_factory=dict)

    @property
    def obstacles(self) -> tuple[Box | Cylinder, ...]:
        """The walls, then the pillars (the order contacts number unnamed ones in)."""
        return (*self.walls, *self.pillars)


def course_worlds() -> list[str]:
    """The names of the course worlds there are."""
    return sorted(path.stem for path in WORLDS_DIR.glob("*.toml"))


@functools.lru_cache(maxsize=None)
def load_course_world(name: str) -> CourseWorld:
    """The course world ``name`` (``sim/course_worlds/<name>.toml``), validated."""
    path = WORLDS_DIR / f"{name}.toml"
    if not path.is_file():
        raise CourseWorldError(f"no course world {name!r}; expected one of {course_worlds()}")
    try:
        world = CourseWorld.model_validate(tomllib.loads(path.read_text(encoding="utf-8")))
    except (tomllib.TOMLDecodeError, ValidationError) as exc:
        raise CourseWorldError(f"{path.name}: {exc}") from None
    if world.name != name:
        raise CourseWorldError(f"{path.name}: name {world.name!r} differs from the file's name")
    return world
