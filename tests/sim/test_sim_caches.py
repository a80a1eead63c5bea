"""The per-process caches: each distinct model compiles once and each start is run once, and every world built from
them runs bit-identically to one built from scratch. A late start waits at rest after the robot has settled."""
from __future__ import annotations

import hashlib

import numpy as np
import pytest

from sim import Scenario, ScriptedCommand, World, load_robot
from sim.model import _compile, build_model
from sim import world as world_module
from sim.world import SETTLE_NS, START_STATES, _start_key, _start_states

WALL = {"kind": "box", "x": 1.0, "y": 0.0, "length": 0.2, "width": 2.0}
PILLAR = {"kind": "cylinder", "x": 0.0, "y": 0.8, "radius": 0.1}


def _scenario(**fields: object) -> Scenario:
    script = [ScriptedCommand(t=0.0, linear=0.15, angular=0.4), ScriptedCommand(t=1.5, linear=0.1, angular=-0.6)]
    defaults: dict[str, object] = {"start_time": 0.5, "script": script, "initial_pose": {"x": 0.2, "yaw": 0.3}}
    return Scenario(duration=3.0, **{**defaults, **fields})


def _clear_caches() -> None:
    _compile.cache_clear()
    _start_states.clear()


def _digest(world: World) -> str:
    """Every sample (repr: exact floats) and the final state of a run in 10 ms advances."""
    digest = hashlib.sha256()
    t_ns = world.time_ns
    while t_ns < world.end_ns:
        t_ns = min(t_ns + 10_000_000, world.end_ns)
        digest.update(repr(world.advance_to(t_ns)).encode())
    digest.update(world.data.qpos.tobytes() + world.data.qvel.tobytes() + world.data.qacc_warmstart.tobytes())
    return digest.hexdigest()


def test_the_same_model_compiles_once_per_process() -> None:
    profile = load_robot("turtlebot3_burger")
    build_model(profile, 1.0, ())
    hits = _compile.cache_info().hits
    build_model(profile, 1.0, ())
    assert _compile.cache_info().hits == hits + 1


def test_imperfections_and_obstacles_compile_their_own_model() -> None:
    profile = load_robot("turtlebot3_burger")
    _compile.cache_clear()
    build_model(profile)
    build_model(profile, 1.02)
    build_model(profile, 1.0, Scenario(obstacles=[WALL]).obstacles)
    assert _compile.cache_info().misses == 3 and _compile.cache_info().hits == 0


def test_every_world_owns_its_model_and_data() -> None:
    first, second = World(_scenario()), World(_scenario())
    assert first.model is not second.model
    assert first.data is not second.data


def test_a_world_that_changes_its_model_leaves_the_next_world_alone() -> None:
    reference = _digest(World(_scenario()))
    spoiled = World(_scenario())
    spoiled.model.geom_friction[:] = 0.0
    spoiled.model.opt.gravity[:] = (0.0, 0.0, -1.0)
    _digest(spoiled)
    assert _digest(World(_scenario())) == reference


@pytest.mark.parametrize(("robot", "fields"), [
    ("turtlebot3_waffle", {}),
    ("turtlebot3_waffle", {"base_mode": "real", "imperfections": {"wheel_radius_error": 0.02, "slip": 0.05}}),
    ("turtlebot3_burger", {"obstacles": [WALL, PILLAR]}),
    ("husky_a200", {"imperfections": {"slip": 0.1}}),
])
def test_a_cached_model_and_start_run_bit_identically_to_fresh_ones(robot: str, fields: dict[str, object]) -> None:
    _clear_caches()
    fresh = _digest(World(_scenario(robot=robot, **fields)))
    assert _compile.cache_info().misses == 1 and len(_start_states) == 1
    cached = [_digest(World(_scenario(robot=robot, **fields))) for _ in range(2)]
    assert _compile.cache_info().hits == 2
    assert cached == [fresh, fresh]


@pytest.mark.parametrize("start_time", [0.001, 1.2345678911, 12.3])
def test_a_world_from_a_saved_start_with_another_script_runs_as_if_built_from_scratch(start_time: float) -> None:
    other = [ScriptedCommand(t=0.0, linear=-0.1, angular=1.0), ScriptedCommand(t=0.7, linear=0.2)]
    _clear_caches()
    fresh = _digest(World(_scenario(start_time=start_time, script=other)))
    _clear_caches()
    World(_scenario(start_time=start_time))  # the same start, its own script
    restored = World(_scenario(start_time=start_time, script=other))
    assert len(_start_states) == 1
    assert _digest(restored) == fresh


def test_a_start_differs_by_pose_mode_imperfections_and_obstacles() -> None:
    _clear_caches()
    for fields in ({}, {"initial_pose": {"x": 0.2, "yaw": -0.3}}, {"base_mode": "real"},
                   {"imperfections": {"slip": 0.02}}, {"obstacles": [WALL]}, {"start_time": 0.6}):
        World(_scenario(**fields))
    assert len(_start_states) == 6


def test_a_world_starting_at_zero_keeps_no_start() -> None:
    _clear_caches()
    World(_scenario(start_time=0.0))
    assert not _start_states


def test_the_saved_starts_are_bounded_least_recently_used_first() -> None:
    _clear_caches()
    scenarios = [_scenario(start_time=0.05 + i / 600) for i in range(START_STATES + 1)]
    keys = [_start_key(load_robot(s.robot), "gazebo", s, s.start_ns) for s in scenarios]
    for scenario in scenarios[:START_STATES]:
        World(scenario)
    World(scenarios[0])  # used again: now the most recent
    World(scenarios[START_STATES])
    assert len(_start_states) == START_STATES
    assert keys[0] in _start_states and keys[1] not in _start_states and keys[START_STATES] in _start_states


def _samples(world: World) -> list:
    samples = []
    t_ns = world.time_ns
    while t_ns < world.end_ns:
        t_ns = min(t_ns + 10_000_000, world.end_ns)
        samples += world.advance_to(t_ns)
    return samples


@pytest.mark.parametrize("robot", ["turtlebot3_waffle", "turtlebot3_burger", "husky_a200"])
def test_a_late_start_waits_at_rest_from_the_settled_robot(robot: str) -> None:
    _clear_caches()
    settled = World(_scenario(robot=robot, start_time=SETTLE_NS / 1e9))
    late = World(_scenario(robot=robot, start_time=40.0))
    assert len(_start_states) == 1  # one settled robot for both starts
    assert late.time_ns == 40_000_000_000
    assert late.data.qpos.tobytes() == settled.data.qpos.tobytes()
    assert late.data.qvel.tobytes() == settled.data.qvel.tobytes()


@pytest.mark.parametrize("robot", ["turtlebot3_waffle", "husky_a200"])
def test_a_run_after_a_wait_at_rest_is_the_run_after_a_simulated_wait(robot: str, monkeypatch) -> None:
    """The same samples at the same times, to within nanometres: physics would only have crept the robot."""
    _clear_caches()
    rested = _samples(World(_scenario(robot=robot, start_time=12.3)))
    monkeypatch.setattr(world_module, "SETTLE_NS", 13_000_000_000)
    simulated_world = World(_scenario(robot=robot, start_time=12.3))
    assert len(_start_states) == 2
    simulated = _samples(simulated_world)
    assert [(type(s), s.t_ns) for s in rested] == [(type(s), s.t_ns) for s in simulated]
    rested_poses = np.array([s.position for s in rested if hasattr(s, "position")])
    simulated_poses = np.array([s.position for s in simulated if hasattr(s, "position")])
    assert rested_poses.shape == simulated_poses.shape and len(rested_poses) > 100
    assert np.abs(rested_poses - simulated_poses).max() < 1e-6
    assert rested_poses.tobytes() != simulated_poses.tobytes()  # the creep is there, and it is that small


def test_a_robot_still_moving_when_settled_is_simulated_to_its_start(monkeypatch) -> None:
    monkeypatch.setattr(world_module, "REST_SPEED", 0.0)  # nothing counts as at rest
    _clear_caches()
    moving = _digest(World(_scenario(start_time=12.3)))
    monkeypatch.setattr(world_module, "SETTLE_NS", 13_000_000_000)  # physics all the way to the start
    assert _digest(World(_scenario(start_time=12.3))) == moving
