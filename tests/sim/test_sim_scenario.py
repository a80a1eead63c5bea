"""Scenario validation and the conversion of its times to integer nanoseconds."""
from __future__ import annotations

import pytest
from pydantic import ValidationError

from sim import Imperfections, Pose2D, Scenario, ScriptedCommand


def test_defaults() -> None:
    scenario = Scenario()
    assert scenario.robot == "turtlebot3_waffle"
    assert scenario.base_mode is None
    assert scenario.initial_pose == Pose2D(x=0.0, y=0.0, yaw=0.0)
    assert (scenario.start_ns, scenario.end_ns) == (2_000_000_000, 62_000_000_000)
    assert scenario.shutdown_ns is None


def test_times_become_integer_nanoseconds() -> None:
    scenario = Scenario(start_time=1.5, duration=10.0, shutdown_at=3.3)
    assert scenario.start_ns == 1_500_000_000
    assert scenario.end_ns == 11_500_000_000
    assert scenario.shutdown_ns == 4_800_000_000
    assert ScriptedCommand(t=0.1).t_ns == 100_000_000


def test_scripted_command_numbers_are_linear_x_and_angular_z() -> None:
    command = ScriptedCommand(t=1.0, linear=0.2, angular=-0.5)
    assert command.linear == (0.2, 0.0, 0.0)
    assert command.angular == (0.0, 0.0, -0.5)
    assert ScriptedCommand(t=0, linear=(0.1, 0.2, 0.3)).linear == (0.1, 0.2, 0.3)


def test_wheel_radius_scale_combines_error_and_slip() -> None:
    assert Imperfections(wheel_radius_error=0.02).wheel_radius_scale == pytest.approx(1.02)
    assert Imperfections(slip=0.05).wheel_radius_scale == pytest.approx(1 / 1.05)


def test_unknown_robot_is_a_clear_error() -> None:
    with pytest.raises(ValidationError, match=r"unknown robot 'r2d2'; available: husky_a200, turtlebot2"):
        Scenario(robot="r2d2")


def test_unknown_base_mode_lists_the_modes() -> None:
    with pytest.raises(ValidationError, match=r"base_mode 'fake' is not a mode of turtlebot3_waffle; expected one of \['gazebo', 'real'\]"):
        Scenario(base_mode="fake")


def test_script_must_be_in_time_order() -> None:
    with pytest.raises(ValidationError, match=r"script\[1\].t = 1.0 s comes before script\[0\].t = 2.0 s"):
        Scenario(script=[ScriptedCommand(t=2.0), ScriptedCommand(t=1.0)])


def test_script_must_end_within_the_run() -> None:
    with pytest.raises(ValidationError, match=r"script\[0\].t = 11.0 s is after the end of the run \(duration 10.0 s\)"):
        Scenario(duration=10.0, script=[ScriptedCommand(t=11.0)])


def test_shutdown_must_be_within_the_run() -> None:
    with pytest.raises(ValidationError, match=r"shutdown_at 20.0 s is after the end of the run"):
        Scenario(duration=10.0, shutdown_at=20.0)


@pytest.mark.parametrize(
    ("fields", "where"),
    [
        ({"start_time": -1.0}, "start_time"),
        ({"duration": 0.0}, "duration"),
        ({"imperfections": {"wheel_radius_error": 0.7}}, "imperfections.wheel_radius_error"),
        ({"imperfections": {"slip": -0.1}}, "imperfections.slip"),
        ({"initial_pose": {"x": float("nan")}}, "initial_pose.x"),
        ({"script": [{"t": -0.5}]}, "script.0.t"),
        ({"durration": 5.0}, "durration"),
    ],
)
def test_bad_fields_are_named(fields: dict[str, object], where: str) -> None:
    with pytest.raises(ValidationError) as info:
        Scenario(**fields)
    assert where in str(info.value)


def test_scenario_round_trips_through_json() -> None:
    scenario = Scenario(robot="husky_a200", initial_pose=Pose2D(x=1.0, yaw=0.5), script=[ScriptedCommand(t=0.5, linear=0.3)])
    assert Scenario.model_validate_json(scenario.model_dump_json()) == scenario
