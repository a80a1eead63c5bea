"""Base drivers without physics: timeouts, the OpenCR firmware arithmetic, ramps and limiters."""
from __future__ import annotations

import math

import pytest

from sim import load_robot
from sim.base_driver import CommandLatch, DiffDriveController, GazeboDiffDrive, OpenCrFirmware, make_driver

WAFFLE = load_robot("turtlebot3_waffle")
HUSKY = load_robot("husky_a200")


def test_latch_is_zero_before_the_first_command() -> None:
    assert CommandLatch(None).command_at(10**9) == (0.0, 0.0)


def test_latch_without_timeout_holds_forever() -> None:
    latch = CommandLatch(None)
    latch.receive(0, 0.2, 0.1)
    assert latch.command_at(10**12) == (0.2, 0.1)


def test_latch_times_out_strictly_after_the_timeout() -> None:
    latch = CommandLatch(500_000_000)
    latch.receive(1_000_000_000, 0.2, 0.0)
    assert latch.command_at(1_500_000_000) == (0.2, 0.0)
    assert latch.command_at(1_500_000_001) == (0.0, 0.0)


def test_latch_holds_its_command_until_received_plus_timeout() -> None:
    assert CommandLatch(None).holds_until_ns() is None
    timed = CommandLatch(500_000_000)
    assert timed.holds_until_ns() is None  # nothing received: nothing to hold
    timed.receive(1_000_000_000, 0.2, 0.0)
    assert timed.holds_until_ns() == 1_500_000_000


def test_a_renewed_command_holds_a_timeout_past_the_renewal() -> None:
    """What a run ahead leaves to do for a node that repeated the command: only the timeout starts again."""
    latch = CommandLatch(500_000_000)
    latch.receive(1_000_000_000, 0.2, 0.1)
    latch.renew(1_400_000_000)
    assert latch.command_at(1_900_000_000) == (0.2, 0.1)
    assert latch.command_at(1_900_000_001) == (0.0, 0.0)
    assert latch.holds_until_ns() == 1_900_000_000


def test_latch_reads_non_finite_values_as_zero() -> None:
    latch = CommandLatch(None)
    latch.receive(0, math.nan, math.inf)
    assert latch.command_at(0) == (0.0, 0.0)


def _firmware_twist(driver: OpenCrFirmware, linear: float, angular: float) -> tuple[float, float]:
    left, right = driver.tick(linear, angular)
    return (left + right) / 2, (right - left) / WAFFLE.geometry.wheel_separation


def test_opencr_truncates_0p1_0p2_to_units_90_and_162() -> None:
    _, driver = make_driver(WAFFLE.modes["real"], WAFFLE.geometry)
    assert isinstance(driver, OpenCrFirmware)
    units_per_mps = 60 / (2 * math.pi * 0.033 * 0.229)
    left, right = driver.tick(0.1, 0.2)
    assert (round(left * units_per_mps, 9), round(right * units_per_mps, 9)) == (90, 162)
    v, w = _firmware_twist(driver, 0.1, 0.2)
    assert v == pytest.approx(0.09971, abs=1e-5)
    assert w == pytest.approx(0.19853, abs=1e-5)
    assert v / w == pytest.approx(0.50225, abs=5e-5)  # +0.45 % on the 0.5 m circle


def test_opencr_clips_each_wheel_at_330_units() -> None:
    _, driver = make_driver(WAFFLE.modes["real"], WAFFLE.geometry)
    v, w = _firmware_twist(driver, 0.26, 1.82)  # right wheel saturates, left truncates to -1
    assert v == pytest.approx(0.13018, abs=1e-5)
    assert w == pytest.approx(0.91269, abs=1e-5)


def test_opencr_clamps_the_twist() -> None:
    _, driver = make_driver(WAFFLE.modes["real"], WAFFLE.geometry)
    v, _ = _firmware_twist(driver, 0.5, 0.0)
    assert v == pytest.approx(0.2612, abs=1e-4)  # 330 units; the 0.2661 twist clamp is above it


def test_gazebo_ramps_the_rims_at_1_m_per_s2_per_tick() -> None:
    _, driver = make_driver(WAFFLE.modes["gazebo"], WAFFLE.geometry)
    assert isinstance(driver, GazeboDiffDrive)
    rims = [driver.tick(0.2, 0.0) for _ in range(7)]
    assert rims[0] == pytest.approx((1 / 30, 1 / 30))
    assert rims[4][0] == pytest.approx(5 / 30)
    assert rims[5] == pytest.approx((0.2, 0.2)) and rims[6] == pytest.approx((0.2, 0.2))
    assert driver.tick(0.0, 0.0) == pytest.approx((0.2 - 1 / 30, 0.2 - 1 / 30))


def test_diff_drive_controller_limits_acceleration_then_speed() -> None:
    _, driver = make_driver(HUSKY.modes["diff_drive_controller"], HUSKY.geometry)
    assert isinstance(driver, DiffDriveController)
    speeds = [sum(driver.tick(2.0, 0.0)) / 2 for _ in range(20)]
    assert speeds[0] == pytest.approx(0.06)  # 3 m/s² x 20 ms
    assert speeds[15] == pytest.approx(0.96)
    assert speeds[16:] == pytest.approx([1.0] * 4)


def test_diff_drive_controller_limits_linear_and_angular_independently() -> None:
    _, driver = make_driver(HUSKY.modes["diff_drive_controller"], HUSKY.geometry)
    for _ in range(50):
        left, right = driver.tick(0.5, 5.0)
    assert (left + right) / 2 == pytest.approx(0.5)
    assert (right - left) / HUSKY.geometry.wheel_separation == pytest.approx(2.0)


def test_kobuki_passes_the_command_straight_through() -> None:
    kobuki = load_robot("turtlebot2")
    latch, driver = make_driver(kobuki.modes["kobuki"], kobuki.geometry)
    assert driver.tick(0.2, 1.0) == pytest.approx((0.2 - 0.115, 0.2 + 0.115))
    latch.receive(0, 0.2, 0.0)
    assert latch.command_at(600_000_000) == (0.2, 0.0)
    assert latch.command_at(600_000_001) == (0.0, 0.0)
