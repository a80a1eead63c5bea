"""The robot's sensor topics: /imu, /joint_states and /scan as declared by the profile, at their rates, with values
that follow the physics (ranges to obstacles, gravity at rest, wheel angles) and the same bits on every run."""
from __future__ import annotations

import math

import pytest

from sim import ImuSample, JointStateSample, Pose2D, Scenario, ScanSample, ScriptedCommand, World
from sim import sensors
from sim.profile import load_robot

SECOND = 1_000_000_000
WALL = {"kind": "box", "x": 1.5, "y": 0.0, "length": 0.2, "width": 6.0}
PILLAR = {"kind": "cylinder", "x": 0.0, "y": 1.0, "radius": 0.15}


def _samples(scenario: Scenario, seconds: float = 1.0) -> list:
    world = World(scenario)
    return world.advance_to(world.start_ns + round(seconds * SECOND))


def _of(samples: list, kind: type) -> list:
    return [s for s in samples if isinstance(s, kind)]


@pytest.fixture(scope="module")
def walled() -> list:
    return _samples(Scenario(obstacles=[WALL, PILLAR]))


def test_turtlebot3_declares_its_gazebo_topics():
    topics = {(t.topic, t.type, t.rate_hz) for t in World(Scenario()).publications if t.to_nodes}
    assert {("/imu", "sensor_msgs/Imu", 200), ("/joint_states", "sensor_msgs/JointState", 30),
            ("/scan", "sensor_msgs/LaserScan", 5), ("/odom", "nav_msgs/Odometry", 30)} <= topics


def test_ground_truth_is_declared_for_the_grader_only():
    truth = [t for t in World(Scenario()).publications if t.topic == "/ground_truth/odom"]
    assert len(truth) == 1 and not truth[0].to_nodes


def test_kobuki_declares_no_sensors():
    assert {t.type for t in World(Scenario(robot="turtlebot2")).publications} == {"nav_msgs/Odometry",
                                                                                 "tf2_msgs/TFMessage"}


def test_rates_over_one_second(walled):
    assert len(_of(walled, ImuSample)) == 200
    assert len(_of(walled, JointStateSample)) == 30
    assert len(_of(walled, ScanSample)) == 5


def test_empty_world_scan_is_all_inf():
    scans = _of(_samples(Scenario()), ScanSample)
    assert scans and all(math.isinf(r) for s in scans for r in s.ranges)


def test_scan_geometry_matches_the_gazebo_sensor(walled):
    scan = _of(walled, ScanSample)[-1]
    assert (scan.frame_id, len(scan.ranges), scan.angle_min, scan.angle_max) == ("base_scan", 360, 0.0, 6.28319)
    assert scan.angle_increment == pytest.approx(6.28319 / 359)
    assert (scan.range_min, scan.range_max) == (0.12, 3.5)


def test_scan_measures_the_wall_ahead_and_the_pillar_to_the_left(walled):
    scan = _of(walled, ScanSample)[-1]
    mount_x = -0.064  # base_scan is 6.4 cm behind base_footprint on the Waffle
    noise = 0.01 * sensors.noise(0, scan.t_ns, 360)  # the profile's Gaussian noise, seed 0
    assert scan.ranges[0] == pytest.approx(1.4 - mount_x + noise[0], abs=1e-6)  # the wall's near face is at x = 1.4
    beam = round(math.atan2(1.0, -mount_x) / scan.angle_increment)
    expected = math.hypot(1.0, -mount_x) - 0.15
    assert scan.ranges[beam] == pytest.approx(expected + noise[beam], abs=0.01)
    assert math.isinf(scan.ranges[180])  # behind: nothing within 3.5 m


def test_scan_turns_with_the_robot():
    turned = _of(_samples(Scenario(obstacles=[WALL], initial_pose=Pose2D(yaw=math.pi / 2))), ScanSample)[-1]
    assert math.isinf(turned.ranges[0])
    assert turned.ranges[270] == pytest.approx(1.4 + 0.0, abs=0.08)  # the wall is now on the robot's right


def test_beyond_range_max_reads_inf():
    far = {"kind": "box", "x": 4.0, "y": 0.0, "length": 0.2, "width": 2.0}
    scan = _of(_samples(Scenario(obstacles=[far])), ScanSample)[-1]
    assert math.isinf(scan.ranges[0])


def test_imu_at_rest_reads_gravity_and_the_heading():
    imu = _of(_samples(Scenario(initial_pose=Pose2D(yaw=1.0))), ImuSample)[-1]
    assert imu.frame_id == "imu_link"
    assert imu.linear_acceleration[2] == pytest.approx(9.81, abs=1e-3)
    assert abs(imu.linear_acceleration[0]) < 1e-3 and abs(imu.linear_acceleration[1]) < 1e-3
    assert imu.orientation[2] == pytest.approx(math.sin(0.5), abs=1e-6)
    assert imu.orientation[3] == pytest.approx(math.cos(0.5), abs=1e-6)


def test_imu_sees_the_turn_rate_and_the_forward_acceleration():
    script = [ScriptedCommand(t=0.0, linear=0.2, angular=0.5)]
    samples = _samples(Scenario(script=script), seconds=3.0)
    imus = _of(samples, ImuSample)
    assert imus[-1].angular_velocity[2] == pytest.approx(0.5, rel=0.01)
    # the 1 m/s² wheel ramp (stepped by the 30 Hz control tick): about 1 m/s² forward on average while speeding up
    ramp = [s.linear_acceleration[0] for s in imus if s.t_ns < samples[0].t_ns + SECOND // 10]
    assert sum(ramp) / len(ramp) == pytest.approx(1.0, abs=0.2)


def test_joint_states_follow_the_wheels():
    script = [ScriptedCommand(t=0.0, linear=0.1)]
    states = _of(_samples(Scenario(script=script), seconds=2.0), JointStateSample)
    first, last = states[0], states[-1]
    assert last.names == ("wheel_left_joint", "wheel_right_joint") and last.velocities == ()
    travelled = (last.positions[0] - first.positions[0]) * load_robot("turtlebot3_waffle").geometry.wheel_radius
    assert travelled == pytest.approx(0.1 * (last.t_ns - first.t_ns) / SECOND, abs=0.02)


def test_husky_joint_states_name_four_wheels_with_velocities():
    state = _of(_samples(Scenario(robot="husky_a200")), JointStateSample)[-1]
    assert state.names == ("front_left_wheel", "front_right_wheel", "rear_left_wheel", "rear_right_wheel")
    assert len(state.velocities) == 4


def test_sensors_are_bit_identical_on_repeat():
    scenario = Scenario(obstacles=[WALL, PILLAR], script=[ScriptedCommand(t=0.0, linear=0.2, angular=0.4)])
    assert _samples(scenario, 2.0) == _samples(scenario, 2.0)


def test_obstacles_stop_the_robot():
    crash = Scenario(obstacles=[{"kind": "box", "x": 0.6, "y": 0.0, "length": 0.2, "width": 2.0}],
                     script=[ScriptedCommand(t=0.0, linear=0.2)])
    world = World(crash)
    world.advance_to(world.start_ns + 6 * SECOND)
    # the base's collision box reaches 0.069 m ahead of the axle, beyond the wheels: it stops against the wall's face
    assert world.state()["x"] == pytest.approx(0.5 - 0.069, abs=0.005)


def test_obstacle_needs_its_kind():
    with pytest.raises(ValueError, match="kind"):
        Scenario(obstacles=[{"x": 1.0, "y": 0.0, "radius": 0.1}])


# -- sensors nobody listens to -------------------------------------------------------------------------------------

_ACCELERATING = Scenario(script=[ScriptedCommand(t=0.0, linear=0.1, angular=0.5),
                                 ScriptedCommand(t=0.4, linear=0.26, angular=-1.0)])


def _advance_in_chunks(world: World, ends_ms: list[int]) -> list:
    out = []
    for end in ends_ms:
        out += world.advance_to(world.start_ns + end * 1_000_000)
    return out


def test_unheard_sensors_are_not_published():
    world = World(_ACCELERATING)
    world.listen({"/odom"})
    samples = world.advance_to(world.start_ns + SECOND)
    assert not _of(samples, ImuSample) and not _of(samples, JointStateSample) and not _of(samples, ScanSample)


def test_imu_heard_again_reads_what_an_always_heard_imu_reads():
    # Chunk ends off the 200 Hz grid, so the IMU's last unheard sample time falls inside a chunk, between two ticks.
    ends = [7, 123, 250, 251, 404, 611, 777, 1000]
    heard = _of(_advance_in_chunks(World(_ACCELERATING), ends), ImuSample)
    world = World(_ACCELERATING)
    world.listen({"/odom"})
    _advance_in_chunks(world, ends[:5])
    world.listen({"/imu"})
    later = _of(_advance_in_chunks(world, ends[5:]), ImuSample)
    assert later and later[0].t_ns > world.start_ns + 404_000_000
    assert later == [s for s in heard if s.t_ns >= later[0].t_ns]
    assert any(abs(s.linear_acceleration[0]) > 0.1 for s in later[:15])  # the 0.4 s command speeds it up


def test_physics_does_not_depend_on_which_sensors_are_heard():
    everything = World(_ACCELERATING)
    odometry_only = World(_ACCELERATING)
    odometry_only.listen({"/odom"})
    ends = [3, 99, 500, 1000]
    _advance_in_chunks(everything, ends)
    _advance_in_chunks(odometry_only, ends)
    assert everything.state() == odometry_only.state()
