"""turtlesim's kinematic world against a closed-form replay of turtle.cpp's update, its 1 s timeout and its clamping."""
from __future__ import annotations

import math

import pytest

from sim import (ColorSample, CommandSample, GroundTruthSample, LogSample, Scenario, ScriptedCommand,
                 TurtlePoseSample, TurtlesimError, open_world)
from sim.turtlesim import CANVAS_M, DT, TURTLE_PI, UPDATE_NS, TurtlesimWorld

CENTRE = CANVAS_M / 2


def run(script: list[ScriptedCommand], duration: float = 3.0, **scenario: object) -> tuple[TurtlesimWorld, list]:
    """Advance a turtlesim scenario to its end in 10 ms /clock periods, as the session does."""
    world = open_world(Scenario(robot="turtlesim", duration=duration, script=script, **scenario))
    assert isinstance(world, TurtlesimWorld)
    samples = []
    t = world.time_ns
    while t < world.end_ns:
        t = min(t + 10_000_000, world.end_ns)
        samples += world.advance_to(t)
    return world, samples


def poses(samples: list) -> list[TurtlePoseSample]:
    return [s for s in samples if isinstance(s, TurtlePoseSample) and s.topic == "/turtle1/pose"]


def replay(x: float, y: float, theta: float, v: float, w: float, updates: int) -> tuple[float, float, float]:
    """turtle.cpp's update ``updates`` times with a constant command: θ first, wrapped, then x, y along it."""
    for _ in range(updates):
        theta += w * DT
        theta -= 2 * TURTLE_PI * math.floor((theta + TURTLE_PI) / (2 * TURTLE_PI))
        x += math.cos(theta) * v * DT
        y += math.sin(theta) * v * DT
    return x, y, theta


def test_turtle1_starts_at_the_centre_heading_east() -> None:
    world = open_world(Scenario(robot="turtlesim", duration=1.0))
    assert world.state()["x"] == pytest.approx(5.544445, abs=1e-6)
    assert world.state()["y"] == pytest.approx(5.544445, abs=1e-6)
    assert world.state()["yaw"] == 0.0
    assert CANVAS_M == pytest.approx(11.088889, abs=1e-6)


def test_poses_come_every_16_ms_on_integer_nanoseconds() -> None:
    _, samples = run([], duration=1.0)
    times = [s.t_ns for s in poses(samples)]
    assert all(t % UPDATE_NS == 0 for t in times)
    assert {b - a for a, b in zip(times, times[1:])} == {UPDATE_NS}


def test_open_loop_motion_matches_the_closed_form_update() -> None:
    # The command is applied at the 2.0 s update (125 * 16 ms) and held by repeats every 0.5 s.
    script = [ScriptedCommand(t=i * 0.5, linear=1.3, angular=0.7) for i in range(4)]
    _, samples = run(script, duration=2.0)
    last = poses(samples)[-1]
    updates = (last.t_ns - 2_000_000_000) // UPDATE_NS + 1
    x, y, theta = replay(CENTRE, CENTRE, 0.0, 1.3, 0.7, updates)
    assert (last.x, last.y, last.theta) == pytest.approx((x, y, theta), abs=1e-12)


def test_theta_wraps_into_minus_pi_to_pi() -> None:
    script = [ScriptedCommand(t=i * 0.5, angular=3.0) for i in range(8)]
    _, samples = run(script, duration=4.0)
    thetas = [p.theta for p in poses(samples)]
    assert min(thetas) >= -TURTLE_PI and max(thetas) < TURTLE_PI
    assert any(b < a - 6 for a, b in zip(thetas, thetas[1:]))  # it did wrap


def test_a_command_older_than_one_second_is_zeroed() -> None:
    _, samples = run([ScriptedCommand(t=0.0, linear=1.0)], duration=3.0)
    moving = [p for p in poses(samples) if p.linear_velocity > 0]
    # Commanded at 2.0 s: the updates at most 1 s later still move (the last is 2.992 s); 3.008 s is > 1 s old.
    assert moving[-1].t_ns == 2_992_000_000
    last = poses(samples)[-1]
    assert last.linear_velocity == 0.0
    assert last.x == pytest.approx(CENTRE + 1.0 * DT * 63, abs=1e-9)  # 63 updates in [2.0, 3.0] s


def test_a_fresh_command_resets_the_timeout() -> None:
    script = [ScriptedCommand(t=0.0, linear=1.0), ScriptedCommand(t=0.9, linear=1.0)]
    _, samples = run(script, duration=3.0)
    moving = [p for p in poses(samples) if p.linear_velocity > 0]
    assert moving[-1].t_ns == 3_888_000_000  # 2.9 s + 1 s, on the last 16 ms update not after it


def test_hitting_the_wall_clamps_and_warns_in_turtle_cpp_words() -> None:
    script = [ScriptedCommand(t=i * 0.5, linear=4.0) for i in range(6)]
    world, samples = run(script, duration=3.0)
    assert world.state()["x"] == CANVAS_M
    warnings = [s for s in samples if isinstance(s, LogSample)]
    assert warnings and all(w.level == 4 and w.name == "/turtlesim" for w in warnings)
    first = warnings[0].msg
    assert first.startswith("Oh no! I hit the wall! (Clamping from [x=11.1")
    assert first.endswith(f", y={CENTRE:f}])")
    assert len(warnings) == sum(1 for p in poses(samples) if p.x == CANVAS_M and p.t_ns >= warnings[0].t_ns)


def test_the_colour_sensor_sees_the_pen_behind_a_moving_turtle() -> None:
    _, samples = run([ScriptedCommand(t=0.0, linear=0.5)], duration=1.0)
    colours = {(s.r, s.g, s.b) for s in samples if isinstance(s, ColorSample) and s.t_ns > 2_100_000_000}
    assert colours == {(179, 184, 255)}


def test_the_colour_sensor_sees_the_background_where_nothing_was_drawn() -> None:
    _, samples = run([], duration=0.5)
    assert {(s.r, s.g, s.b) for s in samples if isinstance(s, ColorSample)} == {(69, 86, 255)}


def test_ground_truth_follows_turtle1_with_its_command() -> None:
    _, samples = run([ScriptedCommand(t=0.0, linear=0.5, angular=0.25)], duration=0.5)
    truth = [s for s in samples if isinstance(s, GroundTruthSample)]
    pose = poses(samples)[-1]
    assert truth[-1].position[:2] == (pose.x, pose.y)
    assert truth[-1].linear[0] == 0.5 and truth[-1].angular[2] == 0.25


def test_a_set_initial_pose_moves_turtle1_before_the_run() -> None:
    world = open_world(Scenario(robot="turtlesim", duration=1.0, initial_pose={"x": 2.0, "y": 3.0, "yaw": 1.0}))
    assert (world.state()["x"], world.state()["y"], world.state()["yaw"]) == pytest.approx((2.0, 3.0, 1.0))


def test_scripted_commands_are_recorded_as_commands() -> None:
    _, samples = run([ScriptedCommand(t=0.5, linear=0.2)], duration=1.0)
    assert [s.t_ns for s in samples if isinstance(s, CommandSample)] == [2_500_000_000]


def test_a_script_on_an_unknown_turtle_is_refused() -> None:
    with pytest.raises(TurtlesimError, match="turtle2/cmd_vel"):
        open_world(Scenario(robot="turtlesim", script=[ScriptedCommand(t=0, linear=1, topic="/turtle2/cmd_vel")]))


def test_turtlesim_scenarios_refuse_robot_only_fields() -> None:
    with pytest.raises(ValueError, match="turtlesim has no base modes"):
        Scenario(robot="turtlesim", base_mode="gazebo")


def test_going_back_in_time_is_refused() -> None:
    world = open_world(Scenario(robot="turtlesim", duration=1.0))
    with pytest.raises(TurtlesimError, match="back in time"):
        world.advance_to(0)


def test_next_output_is_the_next_update_for_a_declared_topic_only() -> None:
    world = open_world(Scenario(robot="turtlesim", duration=1.0))
    assert world.next_output_ns({"/turtle1/pose"}) == 2_000_000_000 + UPDATE_NS
    assert world.next_output_ns({"/odom"}) is None


def test_same_scenario_gives_identical_samples() -> None:
    script = [ScriptedCommand(t=i * 0.3, linear=2.0, angular=1.1) for i in range(10)]
    assert run(script)[1] == run(script)[1]
