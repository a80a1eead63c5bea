"""Helpers shared by the sim tests: run a scripted scenario, pull arrays out of the samples, fit circles."""
from __future__ import annotations

import math

import numpy as np

from sim import GroundTruthSample, OdometrySample, Sample, Scenario, ScriptedCommand, World


def repeat(linear: float, angular: float, start: float, stop: float, hz: float = 10.0) -> list[ScriptedCommand]:
    """The same command every 1/hz s in [start, stop) (like a node's publishing loop)."""
    return [ScriptedCommand(t=start + i / hz, linear=linear, angular=angular) for i in range(round((stop - start) * hz))]


def run(**scenario: object) -> tuple[World, list[Sample]]:
    """Build the scenario's world and advance it to the end in 10 ms /clock periods."""
    world = World(Scenario(**scenario))
    samples: list[Sample] = []
    t_ns = world.time_ns
    while t_ns < world.end_ns:
        t_ns = min(t_ns + 10_000_000, world.end_ns)
        samples += world.advance_to(t_ns)
    return world, samples


def _yaw(q: tuple[float, float, float, float]) -> float:
    x, y, z, w = q
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def truth(world: World, samples: list[Sample]) -> np.ndarray:
    """Ground truth rows: t (s after start), x, y, yaw, vx, vy, wz."""
    return np.array([
        ((s.t_ns - world.start_ns) / 1e9, s.position[0], s.position[1], _yaw(s.orientation), s.linear[0], s.linear[1], s.angular[2])
        for s in samples if isinstance(s, GroundTruthSample)
    ])


def odometry(world: World, samples: list[Sample]) -> np.ndarray:
    """Odometry rows: t (s after start), x, y, yaw, vx, wz."""
    return np.array([
        ((s.t_ns - world.start_ns) / 1e9, s.position[0], s.position[1], _yaw(s.orientation), s.linear[0], s.angular[2])
        for s in samples if isinstance(s, OdometrySample)
    ])


def at(rows: np.ndarray, t: float) -> np.ndarray:
    """The row nearest to time ``t``."""
    return rows[np.argmin(np.abs(rows[:, 0] - t))]


def fit_circle_radius(x: np.ndarray, y: np.ndarray) -> float:
    """Least-squares (Kåsa) circle fit."""
    a = np.c_[x, y, np.ones_like(x)]
    d, e, f = np.linalg.lstsq(a, -(x * x + y * y), rcond=None)[0]
    return math.sqrt(d * d / 4 + e * e / 4 - f)
