"""Kinematics shared by the path metrics: angle wrapping, speeds, distances and when the robot came to rest."""
from __future__ import annotations

import numpy as np

from grader import exact
from grader.metrics.run import Trajectory


def wrap(angle: np.ndarray | float) -> np.ndarray | float:
    """Wrap angles to [-pi, pi): the difference of two headings, whichever side of +-pi they are on."""
    return (np.asarray(angle) + np.pi) % (2.0 * np.pi) - np.pi


def speeds(traj: Trajectory) -> tuple[np.ndarray, np.ndarray]:
    """Speed (m/s) and yaw rate (rad/s) over each interval between consecutive samples."""
    if len(traj) < 2:
        return np.zeros(0), np.zeros(0)
    dt = np.diff(traj.t)
    return np.hypot(np.diff(traj.x), np.diff(traj.y)) / dt, wrap(np.diff(traj.yaw)) / dt


def path_length(traj: Trajectory) -> float:
    """Distance travelled along the path (m)."""
    return exact.total(np.hypot(np.diff(traj.x), np.diff(traj.y))) if len(traj) > 1 else 0.0


def moving(traj: Trajectory, rest_speed: float, rest_turn_rate: float) -> np.ndarray:
    """Per interval: the robot drove or turned faster than the rest thresholds."""
    v, w = speeds(traj)
    return (v > rest_speed) | (np.abs(w) > rest_turn_rate)


def rest_since(traj: Trajectory, rest_speed: float, rest_turn_rate: float) -> float | None:
    """Sim time from which the robot stays at rest until the end of ``traj``; None if it is moving at the end."""
    if len(traj) < 2:
        return None
    m = moving(traj, rest_speed, rest_turn_rate)
    if m[-1]:
        return None
    moving_idx = np.flatnonzero(m)
    return float(traj.t[0] if len(moving_idx) == 0 else traj.t[moving_idx[-1] + 1])


def first_motion(traj: Trajectory, rest_speed: float, rest_turn_rate: float) -> float | None:
    """Sim time at which the robot first moved; None if it never did."""
    idx = np.flatnonzero(moving(traj, rest_speed, rest_turn_rate))
    return None if len(idx) == 0 else float(traj.t[idx[0]])
