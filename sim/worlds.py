"""Which world runs a scenario: turtlesim's kinematic world, or a robot profile in MuJoCo."""
from __future__ import annotations

from sim import turtlesim, world
from sim.scenario import TURTLESIM, Scenario
from sim.turtlesim import TurtlesimWorld
from sim.world import World

WORLD_NODE_NAMES = frozenset({world.NODE_NAME, turtlesim.NODE_NAME})  # the nodes a world stands for


def open_world(scenario: Scenario) -> World | TurtlesimWorld:
    """The world that runs ``scenario`` (both keep the contract in DEVELOPERS.md, so callers need not know which)."""
    return TurtlesimWorld(scenario) if scenario.robot == TURTLESIM else World(scenario)
