"""Determinism: the same scenario in two separate processes gives bit-identical states and sample streams."""
from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

RUN = textwrap.dedent(
    """
    import hashlib, sys
    from sim import Scenario, ScriptedCommand, World
    robot, mode = sys.argv[1], sys.argv[2] or None
    script = [ScriptedCommand(t=t / 10, linear=0.2 if t < 30 else 0.0, angular=0.8 if t % 20 < 10 else -0.5) for t in range(50)]
    world = World(Scenario(robot=robot, base_mode=mode, duration=6.0, initial_pose={"x": 0.3, "yaw": 0.7}, script=script))
    digest = hashlib.sha256()
    t_ns = world.time_ns
    while t_ns < world.end_ns:
        t_ns += 10_000_000
        if t_ns % 70_000_000 == 0:  # a node's commands, on the second topic where there is one
            world.command(world.command_topics[-1], linear=(0.1, 0.0, 0.0), angular=(0.0, 0.0, 0.3))
        digest.update(repr(world.advance_to(t_ns)).encode())
        digest.update(world.data.qpos.tobytes() + world.data.qvel.tobytes())
    print(digest.hexdigest())
    """
)


def _run(robot: str, mode: str) -> str:
    done = subprocess.run([sys.executable, "-c", RUN, robot, mode], capture_output=True, text=True, check=True, timeout=60)
    return done.stdout.strip()


@pytest.mark.parametrize(("robot", "mode"), [("turtlebot3_waffle", ""), ("turtlebot3_waffle", "real"), ("husky_a200", "")])
def test_two_processes_give_bit_identical_runs(robot: str, mode: str) -> None:
    first, second = _run(robot, mode), _run(robot, mode)
    assert len(first) == 64
    assert first == second
