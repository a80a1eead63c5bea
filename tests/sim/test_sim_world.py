"""The world against the exact unicycle and the upstream base behaviours (ground truth, odometry, timeouts, limits)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from sim_testkit import at, fit_circle_radius, odometry, repeat, run, truth

from sim import CommandSample, GroundTruthSample, OdometrySample, Scenario, ScriptedCommand, SimError, TransformSample, World

# -- accuracy against the unicycle (TurtleBot3 Waffle, gazebo mode) -------------------------------------------------


@pytest.fixture(scope="module")
def circle() -> np.ndarray:
    world, samples = run(duration=12.0, script=[ScriptedCommand(t=0.0, linear=0.1, angular=0.2)])
    return truth(world, samples)


def test_circle_radius_within_0p1_percent_of_0p5_m(circle: np.ndarray) -> None:
    settled = circle[circle[:, 0] > 1.0]
    radius = fit_circle_radius(settled[:, 1], settled[:, 2])
    assert abs(radius / 0.5 - 1) < 0.001


@pytest.mark.parametrize(("linear", "angular"), [(0.26, 0.0), (0.0, 1.82)])
def test_steady_twist_within_0p1_percent(linear: float, angular: float) -> None:
    world, samples = run(duration=5.0, script=[ScriptedCommand(t=0.0, linear=linear, angular=angular)])
    steady = truth(world, samples)
    steady = steady[steady[:, 0] > 2.0]
    assert abs(steady[:, 4].mean() - linear) <= 0.001 * max(linear, 0.26)
    assert abs(steady[:, 6].mean() - angular) <= 0.001 * max(angular, 1.82)


@pytest.fixture(scope="module")
def square() -> tuple[World, list]:
    # 0.2 m/s x 5 s sides, π/2 in 3 s turns, 1 s pauses: every duration is whole 30 Hz ticks
    script: list[ScriptedCommand] = []
    for side in range(4):
        t = 10.0 * side
        script += [ScriptedCommand(t=t, linear=0.2), ScriptedCommand(t=t + 5, linear=0.0),
                   ScriptedCommand(t=t + 6, angular=math.pi / 6), ScriptedCommand(t=t + 9, angular=0.0)]
    return run(duration=41.0, initial_pose={"x": -2.0, "y": -0.5}, script=script)


def test_open_loop_square_closes_within_5_mm(square: tuple[World, list]) -> None:
    rows = truth(*square)
    assert math.hypot(rows[-1, 1] + 2.0, rows[-1, 2] + 0.5) < 0.005
    assert abs(rows[-1, 3]) < math.radians(0.1)
    corner = at(rows, 5.9)  # end of the first side
    assert corner[1] == pytest.approx(-1.0, abs=0.005) and corner[2] == pytest.approx(-0.5, abs=0.005)


def test_gazebo_odometry_is_the_world_pose_from_the_spawn_pose(square: tuple[World, list]) -> None:
    world, samples = square
    odom = odometry(world, samples)
    assert odom[0, 0] == pytest.approx(1 / 30, abs=1e-8)
    assert odom[0, 1:4] == pytest.approx([-2.0, -0.5, 0.0], abs=1e-3)
    ground = truth(world, samples)
    assert odom[-1, 1:3] == pytest.approx(at(ground, odom[-1, 0])[1:3], abs=1e-9)


def test_sample_streams_have_the_profile_rates_frames_and_order(square: tuple[World, list]) -> None:
    world, samples = square
    assert [s.t_ns for s in samples] == sorted(s.t_ns for s in samples)
    odom = [s for s in samples if isinstance(s, OdometrySample)]
    tf = [s for s in samples if isinstance(s, TransformSample)]
    ground = [s for s in samples if isinstance(s, GroundTruthSample)]
    commands = [s for s in samples if isinstance(s, CommandSample)]
    assert (len(odom), len(tf), len(ground), len(commands)) == (41 * 30, 41 * 30, 41 * 50, 16)
    assert {(s.topic, s.frame_id, s.child_frame_id) for s in odom} == {("/odom", "odom", "base_footprint")}
    assert {(s.frame_id, s.child_frame_id) for s in tf} == {("odom", "base_footprint")}
    assert ground[0].t_ns == world.start_ns + 20_000_000
    assert commands[1] == CommandSample(world.start_ns + 5_000_000_000, "/cmd_vel", (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    assert odom[0].pose_covariance[0] == 1e-5 and odom[0].pose_covariance[35] == 1e-3


# -- TurtleBot3 real (OpenCR) ------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def real_circle() -> tuple[World, list]:
    return run(base_mode="real", duration=12.0, initial_pose={"x": 1.0, "y": 2.0, "yaw": 1.0}, script=repeat(0.1, 0.2, 0.0, 12.0))


def test_real_mode_reproduces_the_firmware_0p45_percent_radius(real_circle: tuple[World, list]) -> None:
    rows = truth(*real_circle)
    rows = rows[rows[:, 0] > 1.0]
    assert fit_circle_radius(rows[:, 1], rows[:, 2]) == pytest.approx(0.50225, rel=0.001)


def test_dead_reckoning_starts_at_zero_wherever_the_robot_spawns(real_circle: tuple[World, list]) -> None:
    odom = odometry(*real_circle)
    # the first sample is one 30 Hz tick after the start: 3.3 mm and 6.7 mrad of motion at most
    assert odom[0, 1:4] == pytest.approx([0.0, 0.0, 0.0], abs=0.007)
    rows = odom[odom[:, 0] > 1.0]
    assert fit_circle_radius(rows[:, 1], rows[:, 2]) == pytest.approx(0.50225, rel=0.001)


# -- timeouts: the last command is at t = 1.0 s -----------------------------------------------------------------------


def _speeds_after_last_command(robot: str, base_mode: str | None, linear: float) -> np.ndarray:
    world, samples = run(robot=robot, base_mode=base_mode, duration=3.0, script=repeat(linear, 0.0, 0.0, 1.1))
    return truth(world, samples)


def test_tb3_gazebo_holds_the_last_command_forever() -> None:
    world, samples = run(duration=20.0, script=[ScriptedCommand(t=0.0, linear=0.2)])
    assert at(truth(world, samples), 20.0)[4] == pytest.approx(0.2, rel=1e-4)


@pytest.mark.parametrize(
    ("robot", "base_mode", "timeout", "stopping"),
    [("turtlebot3_waffle", "real", 0.5, 0.2), ("husky_a200", None, 0.25, 0.25), ("turtlebot2", None, 0.6, 0.2)],
)
def test_base_stops_after_its_timeout(robot: str, base_mode: str | None, timeout: float, stopping: float) -> None:
    rows = _speeds_after_last_command(robot, base_mode, 0.2)
    assert at(rows, 1.0 + timeout - 0.02)[4] == pytest.approx(0.2, rel=0.01)  # still driving just before
    assert abs(at(rows, 1.0 + timeout + stopping)[4]) < 0.005  # stopped soon after
    assert abs(rows[-1, 4]) < 1e-4


def test_husky_stops_through_its_acceleration_limiter() -> None:
    rows = _speeds_after_last_command("husky_a200", None, 0.9)
    # zeroed at the 50 Hz tick at 1.26 s, then 0.06 m/s less per tick: 0.30 m/s after the 1.44 s tick (+ servo lag)
    assert 0.30 <= at(rows, 1.46)[4] <= 0.36  # the first 50 Hz ground-truth sample after that tick
    assert abs(at(rows, 1.62)[4]) < 0.01


# -- Husky limits ------------------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def husky_fast() -> np.ndarray:
    world, samples = run(robot="husky_a200", duration=2.0, script=repeat(2.0, 5.0, 0.0, 2.0))
    return truth(world, samples)


def test_husky_2_m_per_s_command_reaches_1_m_per_s_at_3_m_per_s2(husky_fast: np.ndarray) -> None:
    assert at(husky_fast, 0.2)[4] == pytest.approx(0.6, abs=0.04)
    assert at(husky_fast, 1.5)[4] == pytest.approx(1.0, rel=1e-3)
    assert husky_fast[:, 4].max() < 1.0 + 1e-3


def test_husky_angular_speed_limited_to_2_rad_per_s_at_6_rad_per_s2(husky_fast: np.ndarray) -> None:
    assert at(husky_fast, 0.2)[6] == pytest.approx(1.2, abs=0.1)
    assert at(husky_fast, 1.5)[6] == pytest.approx(2.0, rel=2e-3)


def test_husky_accepts_its_controller_topic_and_cmd_vel() -> None:
    world = World(Scenario(robot="husky_a200", duration=1.0))
    assert world.command_topics == ("/husky_velocity_controller/cmd_vel", "/cmd_vel")
    assert world.command("/cmd_vel", linear=(0.5, 0.0, 0.0))
    assert world.command("/husky_velocity_controller/cmd_vel", linear=(0.5, 0.0, 0.0))
    assert not world.command("/mobile_base/commands/velocity", linear=(0.5, 0.0, 0.0))
    odom = [s for s in world.advance_to(world.start_ns + 100_000_000) if isinstance(s, OdometrySample)]
    assert [s.t_ns - world.start_ns for s in odom] == [20_000_000, 40_000_000, 60_000_000, 80_000_000, 100_000_000]
    assert (odom[0].topic, odom[0].child_frame_id) == ("/husky_velocity_controller/odom", "base_link")


# -- imperfections -----------------------------------------------------------------------------------------------------


def _one_metre(**imperfections: float) -> tuple[np.ndarray, np.ndarray]:
    world, samples = run(base_mode="real", duration=6.0, imperfections=imperfections, script=repeat(0.2, 0.0, 0.0, 5.0))
    return truth(world, samples), odometry(world, samples)


def test_wheel_radius_error_makes_the_robot_go_farther_than_odometry_says() -> None:
    ground, odom = _one_metre(wheel_radius_error=0.02)
    assert ground[-1, 1] / odom[-1, 1] == pytest.approx(1.02, abs=1e-3)
    assert ground[-1, 1] > 0.99 * 1.02


def test_slip_makes_odometry_over_count_the_motion() -> None:
    ground, odom = _one_metre(slip=0.05)
    assert odom[-1, 1] / ground[-1, 1] == pytest.approx(1.05, abs=1e-3)


# -- the API contract --------------------------------------------------------------------------------------------------


def test_commands_latch_on_the_next_control_tick() -> None:
    world = World(Scenario(duration=1.0))
    assert world.time_ns == world.start_ns == 2_000_000_000
    world.advance_to(world.start_ns + 5_000_000)
    assert world.command("/cmd_vel", linear=(0.2, 0.0, 0.0))
    world.advance_to(world.start_ns + 33_000_000)
    assert world.state()["command_linear"] == 0.0
    world.advance_to(world.start_ns + 34_000_000)  # the 30 Hz tick at 2.0333 s
    assert world.state()["command_linear"] == 0.2
    assert world.state()["wheel_left_target"] == pytest.approx((1 / 30) / 0.033)


def test_unknown_topic_is_not_listened_to() -> None:
    assert not World(Scenario(duration=1.0)).command("/turtle1/cmd_vel", linear=(1.0, 0.0, 0.0))


def test_next_output_ns_is_the_first_sample_of_the_next_advance() -> None:
    world = World(Scenario(duration=1.0, script=[ScriptedCommand(t=0.0, linear=0.1), ScriptedCommand(t=0.015, linear=0.2)]))
    assert world.next_output_ns() == world.start_ns
    first = world.advance_to(world.start_ns)
    assert [type(s) for s in first] == [CommandSample]
    for _ in range(10):
        due = world.next_output_ns()
        samples = world.advance_to(due + 3_000_000)
        assert samples[0].t_ns == due and due > world.start_ns


def test_advance_back_in_time_raises() -> None:
    world = World(Scenario(duration=1.0))
    world.advance_to(world.start_ns + 10_000_000)
    with pytest.raises(SimError, match="cannot advance back in time"):
        world.advance_to(world.start_ns)


def test_script_topic_must_be_a_command_topic() -> None:
    with pytest.raises(SimError, match=r"script\[0\].topic '/odom' is not a command topic"):
        World(Scenario(duration=1.0, script=[ScriptedCommand(t=0.0, topic="/odom")]))


def test_state_names_pose_twist_and_wheels() -> None:
    world = World(Scenario(duration=1.0, initial_pose={"x": 1.0, "y": -1.0, "yaw": 0.5}))
    state = world.state()
    assert {"x", "y", "yaw", "vx", "vy", "wz", "wheel_left", "wheel_right"} <= set(state)
    assert (state["x"], state["y"], state["yaw"]) == pytest.approx((1.0, -1.0, 0.5), abs=1e-6)


def test_the_next_scripted_command_is_known_ahead_until_none_is_left() -> None:
    world = World(Scenario(duration=3.0, script=[ScriptedCommand(t=0.5, linear=0.1), ScriptedCommand(t=1.0)]))
    start = world.time_ns
    assert world.next_scripted_command_ns == start + 500_000_000
    world.advance_to(start + 600_000_000)
    assert world.next_scripted_command_ns == start + 1_000_000_000
    world.advance_to(start + 1_100_000_000)
    assert world.next_scripted_command_ns is None


def test_a_repeated_command_restarts_the_base_timeout_from_when_it_came() -> None:
    """World.repeat_command is what a run ahead owes a node that repeated its command: with it the real TurtleBot3's
    0.5 s timeout runs from the repeat, not from the first command."""
    world = World(Scenario(base_mode="real", duration=3.0))
    start = world.time_ns
    world.command("/cmd_vel", linear=(0.2, 0.0, 0.0))
    assert world.command_holds_until_ns() == start + 500_000_000
    world.advance_to(start + 400_000_000)
    world.repeat_command(start + 300_000_000)
    assert world.command_holds_until_ns() == start + 800_000_000
    world.advance_to(start + 790_000_000)
    assert world.state()["command_linear"] == pytest.approx(0.2)
