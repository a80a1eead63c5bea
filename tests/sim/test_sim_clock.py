"""The clock: physics steps map to exact integer nanoseconds and back."""
from __future__ import annotations

from sim.clock import PHYSICS_HZ, last_step_at, seconds_to_ns, step_ns, steps_per_tick


def test_tick_rates_are_whole_numbers_of_steps() -> None:
    assert PHYSICS_HZ == 600
    assert (steps_per_tick(30), steps_per_tick(50), steps_per_tick(100)) == (20, 12, 6)


def test_50_and_100_hz_ticks_are_exact() -> None:
    assert step_ns(6) == 10_000_000
    assert step_ns(12 * 7) == 140_000_000
    assert step_ns(1200) == 2_000_000_000


def test_30_hz_ticks_floor_to_the_nanosecond() -> None:
    assert step_ns(20) == 33_333_333
    assert step_ns(40) == 66_666_666
    assert step_ns(600) == 1_000_000_000


def test_last_step_at_inverts_step_ns() -> None:
    for k in range(0, 5000, 7):
        t = step_ns(k)
        assert last_step_at(t) == k
        assert last_step_at(t - 1) == k - 1 if k else True
        assert last_step_at(step_ns(k + 1) - 1) == k


def test_seconds_to_ns_rounds() -> None:
    assert seconds_to_ns(0.1) == 100_000_000
    assert seconds_to_ns(2.0) == 2_000_000_000
