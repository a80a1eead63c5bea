"""Robot profiles: the bundled values, and errors that name the file and the field."""
from __future__ import annotations

from pathlib import Path

import pytest

from sim import ProfileError, RobotProfile, available_robots, load_robot
from sim.profile import ROBOTS_DIR, covariance_matrix


def test_available_robots_are_the_four_bundled_profiles() -> None:
    assert available_robots() == ["husky_a200", "turtlebot2", "turtlebot3_burger", "turtlebot3_waffle"]


def test_every_bundled_profile_loads() -> None:
    for name in available_robots():
        assert load_robot(name).name == name


def test_waffle_geometry_and_limits() -> None:
    waffle = load_robot("turtlebot3_waffle")
    assert waffle.geometry.wheel_radius == 0.033
    assert waffle.geometry.wheel_separation == 0.287
    assert (waffle.limits.max_linear, waffle.limits.max_angular) == (0.26, 1.82)
    assert waffle.geometry.com[0] == -0.02


def test_waffle_gazebo_mode_is_default_with_no_timeout_and_world_odometry() -> None:
    waffle = load_robot("turtlebot3_waffle")
    gazebo = waffle.modes[waffle.default_mode]
    assert waffle.default_mode == "gazebo"
    assert gazebo.command_topics == ["/cmd_vel"]
    assert gazebo.command_timeout is None
    assert gazebo.control_rate_hz == 30
    assert (gazebo.odometry.topic, gazebo.odometry.rate_hz, gazebo.odometry.source) == ("/odom", 30, "world")
    assert (gazebo.odometry.frame_id, gazebo.odometry.child_frame_id) == ("odom", "base_footprint")
    assert gazebo.tf is not None and (gazebo.tf.rate_hz, gazebo.tf.parent, gazebo.tf.child) == (30, "odom", "base_footprint")


def test_waffle_real_mode_has_firmware_limits_and_encoder_odometry() -> None:
    real = load_robot("turtlebot3_waffle").modes["real"]
    assert real.command_timeout == 0.5
    assert real.driver.kind == "opencr" and real.driver.wheel_limit_units == 330
    assert real.driver.max_linear == pytest.approx(0.26609, abs=1e-5)
    assert real.odometry.source == "wheels"


def test_burger_wheel_limit_is_265_units() -> None:
    burger = load_robot("turtlebot3_burger")
    assert burger.geometry.wheel_separation == 0.160
    assert burger.modes["real"].driver.wheel_limit_units == 265


def test_husky_controller_parameters() -> None:
    husky = load_robot("husky_a200")
    mode = husky.modes["diff_drive_controller"]
    assert husky.geometry.wheel_radius == 0.1651
    assert husky.geometry.wheel_separation == pytest.approx(1.070, abs=1e-3)
    assert (husky.limits.max_linear, husky.limits.max_angular) == (1.0, 2.0)
    assert mode.command_topics == ["/husky_velocity_controller/cmd_vel", "/cmd_vel"]
    assert mode.command_timeout == 0.25
    assert (mode.driver.max_linear_acceleration, mode.driver.max_angular_acceleration) == (3.0, 6.0)
    assert (mode.odometry.topic, mode.odometry.rate_hz) == ("/husky_velocity_controller/odom", 50)
    assert mode.odometry.child_frame_id == "base_link"


def test_kobuki_parameters() -> None:
    kobuki = load_robot("turtlebot2")
    mode = kobuki.modes[kobuki.default_mode]
    assert mode.command_topics == ["/cmd_vel_mux/input/teleop", "/mobile_base/commands/velocity"]
    assert mode.command_timeout == 0.6
    assert mode.driver.kind == "direct"
    assert (mode.odometry.topic, mode.odometry.rate_hz, mode.odometry.child_frame_id) == ("/odom", 50, "base_footprint")


def test_covariance_matrix_puts_the_diagonal_on_the_diagonal() -> None:
    matrix = covariance_matrix((1.0, 2.0, 3.0, 4.0, 5.0, 6.0))
    assert len(matrix) == 36
    assert [matrix[i * 7] for i in range(6)] == [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
    assert sum(matrix) == 21.0


def _edited_waffle(tmp_path: Path, old: str, new: str, name: str = "turtlebot3_waffle") -> Path:
    text = (ROBOTS_DIR / "turtlebot3_waffle.toml").read_text()
    assert old in text
    path = tmp_path / f"{name}.toml"
    path.write_text(text.replace(old, new, 1))
    return path


def test_unknown_robot_names_the_file_and_lists_the_robots() -> None:
    with pytest.raises(ProfileError, match=r"robots/nosuchbot\.toml: unknown robot 'nosuchbot'; available: husky_a200"):
        load_robot("nosuchbot")


def test_negative_wheel_radius_names_file_field_and_expectation(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, "wheel_radius = 0.033", "wheel_radius = -0.033")
    with pytest.raises(ProfileError) as info:
        RobotProfile.from_toml(path)
    message = str(info.value)
    assert str(path) in message
    assert "field 'geometry.wheel_radius': Input should be greater than 0 (got -0.033)" in message


def test_missing_field_is_named(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, "wheel_mass = 0.0285\n", "")
    with pytest.raises(ProfileError, match=r"field 'geometry.wheel_mass': Field required"):
        RobotProfile.from_toml(path)


def test_misspelt_field_is_rejected(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, "wheel_mass = 0.0285", "wheel_mas = 0.0285")
    with pytest.raises(ProfileError, match=r"field 'geometry.wheel_mas': Extra inputs are not permitted"):
        RobotProfile.from_toml(path)


def test_unknown_driver_kind_is_rejected(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, 'kind = "gazebo_diff_drive"', 'kind = "warp_drive"')
    with pytest.raises(ProfileError, match=r"field 'modes.gazebo.driver'.*'gazebo_diff_drive', 'opencr'"):
        RobotProfile.from_toml(path)


def test_rate_must_divide_the_physics_step(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, "control_rate_hz = 30 ", "control_rate_hz = 70 ")
    with pytest.raises(ProfileError, match=r"modes.gazebo.control_rate_hz = 70: expected a rate that divides the 600 Hz"):
        RobotProfile.from_toml(path)


def test_sensor_rate_must_divide_the_physics_step(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, 'topic = "/scan", rate_hz = 5,', 'topic = "/scan", rate_hz = 7,')
    with pytest.raises(ProfileError, match=r"modes.gazebo.sensors.scan.rate_hz = 7: expected a rate that divides"):
        RobotProfile.from_toml(path)


def test_scan_angles_must_increase(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, "angle_min = 0.0, angle_max = 6.28319", "angle_min = 1.0, angle_max = 0.5")
    with pytest.raises(ProfileError, match=r"expected angle_min < angle_max and range_min < range_max"):
        RobotProfile.from_toml(path)


def test_default_mode_must_exist(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, 'default_mode = "gazebo"', 'default_mode = "sim"')
    with pytest.raises(ProfileError, match=r"default_mode 'sim' is not one of the modes \['gazebo', 'real'\]"):
        RobotProfile.from_toml(path)


def test_name_must_match_the_file_name(tmp_path: Path) -> None:
    path = _edited_waffle(tmp_path, "wheel_mass", "wheel_mass", name="waffle_copy")
    with pytest.raises(ProfileError, match=r"waffle_copy\.toml: field 'name' is 'turtlebot3_waffle'; expected the file name 'waffle_copy'"):
        RobotProfile.from_toml(path)


def test_invalid_toml_names_the_file(tmp_path: Path) -> None:
    path = tmp_path / "broken.toml"
    path.write_text("name = \n")
    with pytest.raises(ProfileError, match=r"broken\.toml: not valid TOML"):
        RobotProfile.from_toml(path)
