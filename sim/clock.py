"""The sim clock: one fixed physics step (1/600 s) and exact integer-nanosecond times for step indices.

600 Hz makes the 30, 50 and 100 Hz ticks of the robots' drivers, odometry, ground truth and clock whole numbers of steps
(20, 12 and 6), so every tick happens on a step and ``step_ns`` is the one place where steps become nanoseconds.
"""
from __future__ import annotations

PHYSICS_HZ = 600
NS_PER_S = 1_000_000_000


def step_ns(k: int) -> int:
    """Sim time of physics step ``k`` (floor of k/600 s in ns; exact for every 50 and 100 Hz tick)."""
    return k * NS_PER_S // PHYSICS_HZ


def last_step_at(t_ns: int) -> int:
    """The last step whose time is at or before ``t_ns`` (the inverse of ``step_ns``)."""
    return ((t_ns + 1) * PHYSICS_HZ - 1) // NS_PER_S


def steps_per_tick(rate_hz: int) -> int:
    """Physics steps between two ticks of a ``rate_hz`` loop (the profile guarantees it divides evenly)."""
    return PHYSICS_HZ // rate_hz


def seconds_to_ns(seconds: float) -> int:
    """Seconds (as written in scenarios and profiles) to integer nanoseconds."""
    return round(seconds * NS_PER_S)
