"""World snapshots: a world restored to a snapshot goes on bit for bit as it went the first time (the session's
rollback of a world run ahead of a node depends on it)."""
from __future__ import annotations

import pytest

from sim import Scenario, ScriptedCommand, World

WALL = {"kind": "box", "x": 0.8, "y": 0.0, "length": 0.2, "width": 2.0}
ROBOTS = ["turtlebot3_burger", "turtlebot3_waffle", "turtlebot2", "husky_a200"]


def _world(robot: str) -> World:
    script = [ScriptedCommand(t=0.0, linear=0.2, angular=0.5), ScriptedCommand(t=1.2, linear=0.15, angular=-0.7)]
    world = World(Scenario(robot=robot, duration=4.0, script=script, obstacles=[WALL]))
    world.listen(None)  # every sensor, the IMU (which keeps state) and the scanner (which reads MuJoCo's data) too
    return world


def _future(world: World, start_ns: int) -> list:
    """Odd-sized advances with a node's command in between: every sample, then the named state at the end."""
    out = list(world.advance_to(start_ns + 333_333_333))
    world.command(world.command_topics[0], linear=(0.1, 0.0, 0.0), angular=(0.0, 0.0, 0.3))
    out += world.advance_to(start_ns + 1_700_000_001)
    out += world.advance_to(start_ns + 2_500_000_000)
    return [repr(out), world.state(), world.time_ns]


@pytest.mark.parametrize("robot", ROBOTS)
def test_a_restored_world_repeats_its_future_bit_for_bit(robot: str) -> None:
    world = _world(robot)
    start = world.time_ns
    world.advance_to(start + 250_000_000)
    snapshot = world.snapshot()
    first = _future(world, start)
    world.restore(snapshot)
    assert _future(world, start) == first


def test_a_restore_undoes_commands_and_scripted_commands_given_after_the_snapshot() -> None:
    world = _world("turtlebot3_waffle")
    start = world.time_ns
    untouched = _future(_world("turtlebot3_waffle"), start)
    snapshot = world.snapshot()
    world.command(world.command_topics[0], linear=(0.26, 0.0, 0.0))  # a command the restore must forget
    world.advance_to(start + 2_000_000_000)  # past the second scripted command
    world.restore(snapshot)
    assert world.time_ns == start
    assert _future(world, start) == untouched


def test_a_snapshot_can_be_restored_again_after_the_restored_world_has_moved_on() -> None:
    world = _world("turtlebot3_burger")
    start = world.time_ns
    snapshot = world.snapshot()
    first = _future(world, start)
    world.restore(snapshot)
    world.command(world.command_topics[0], linear=(-0.2, 0.0, 0.0), angular=(0.0, 0.0, 2.0))
    world.advance_to(start + 900_000_000)  # moves the restored parts on: the snapshot's must not move with them
    world.restore(snapshot)
    assert _future(world, start) == first
