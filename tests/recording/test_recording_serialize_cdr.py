"""The CDR serializers give exactly rosbags' serialize_cdr bytes; the command decoders read Twist and TwistStamped."""
from __future__ import annotations

import math

import numpy as np
import pytest

from recording_helpers import MessageBuilder, Run
from grader.recording import RecordingError
from grader.recording import serialize_cdr as cdr
from grader.recording.ros2_messages import ros2_catalog
from sim.samples import ColorSample, ImuSample, JointStateSample, LogSample, ScanSample, TurtlePoseSample


def test_odometry_cdr_equals_rosbags(run: Run, ros2_msgs: MessageBuilder) -> None:
    for seq, sample in enumerate(run.odometry):
        assert cdr.odometry_cdr(sample, seq) == ros2_msgs.serialize(ros2_msgs.from_odometry_sample(sample, seq))


def test_ground_truth_cdr_equals_rosbags(run: Run, ros2_msgs: MessageBuilder) -> None:
    for seq, sample in enumerate(run.ground_truth):
        expected = ros2_msgs.serialize(ros2_msgs.from_ground_truth_sample(sample, seq))
        assert cdr.ground_truth_cdr(sample, seq) == expected


def test_tf_cdr_equals_rosbags(run: Run, ros2_msgs: MessageBuilder) -> None:
    for seq, sample in enumerate(run.transforms):
        assert cdr.tf_cdr(sample, seq) == ros2_msgs.serialize(ros2_msgs.from_transform_sample(sample, seq))


@pytest.mark.parametrize("frame_id", ["", "i", "imu_link", "imu_lin"])  # string lengths move the doubles' padding
def test_imu_cdr_equals_rosbags(ros2_msgs: MessageBuilder, frame_id: str) -> None:
    sample = ImuSample(5_000_000_001, "/imu", frame_id, (0.0, -0.0, 0.38, 0.92), (1e-300, 0.0, -1.82),
                       (0.01, -0.2, 9.81))
    t, zero = ros2_msgs.t, np.zeros(9)
    expected = t["sensor_msgs/msg/Imu"](ros2_msgs.header(3, sample.t_ns, frame_id),
                                         t["geometry_msgs/msg/Quaternion"](*sample.orientation), zero,
                                         ros2_msgs.vector3(sample.angular_velocity), zero,
                                         ros2_msgs.vector3(sample.linear_acceleration), zero)
    assert cdr.imu_cdr(sample, 3) == ros2_msgs.serialize(expected)


@pytest.mark.parametrize("velocities", [(), (1.5, -2.25, 0.0, 1e-9)])
def test_joint_state_cdr_equals_rosbags(ros2_msgs: MessageBuilder, velocities: tuple[float, ...]) -> None:
    names = ("wheel_left_joint", "wheel_right_joint", "a", "bc")
    sample = JointStateSample(7_000_000_000, "/joint_states", "", names, (0.5, -0.5, 0.5, 123.25), velocities)
    expected = ros2_msgs.t["sensor_msgs/msg/JointState"](
        ros2_msgs.header(0, sample.t_ns, ""), list(names), np.array(sample.positions), np.array(velocities),
        np.zeros(0))
    assert cdr.joint_state_cdr(sample, 0) == ros2_msgs.serialize(expected)


def test_laser_scan_cdr_equals_rosbags(ros2_msgs: MessageBuilder) -> None:
    ranges = tuple([math.inf] * 358 + [0.5, 3.5])
    sample = ScanSample(9_200_000_000, "/scan", "base_scan", 0.0, 6.28319, 6.28319 / 359, 0.12, 3.5, ranges)
    expected = ros2_msgs.t["sensor_msgs/msg/LaserScan"](
        ros2_msgs.header(12, sample.t_ns, "base_scan"), 0.0, 6.28319, 6.28319 / 359, 0.0, 0.0, 0.12, 3.5,
        np.array(ranges, dtype=np.float32), np.zeros(360, dtype=np.float32))
    assert cdr.laser_scan_cdr(sample, 12) == ros2_msgs.serialize(expected)


def test_turtle_messages_equal_rosbags() -> None:
    catalog = ros2_catalog()
    pose = TurtlePoseSample(1, "/turtle1/pose", 5.544445, 5.544445, -3.0, 2.0, -0.5)
    expected = catalog.encode("turtlesim/msg/Pose", catalog.message_class("turtlesim/msg/Pose")(
        x=pose.x, y=pose.y, theta=pose.theta, linear_velocity=pose.linear_velocity,
        angular_velocity=pose.angular_velocity))
    assert cdr.turtle_pose_cdr(pose, 0) == expected
    color = ColorSample(1, "/turtle1/color_sensor", 69, 86, 255)
    assert cdr.color_cdr(color, 0) == catalog.encode(
        "turtlesim/msg/Color", catalog.message_class("turtlesim/msg/Color")(r=69, g=86, b=255))


@pytest.mark.parametrize("text", ["", "a", "ünïcode line", "x" * 1001])
def test_string_and_log_cdr_equal_rosbags(text: str) -> None:
    catalog = ros2_catalog()
    assert cdr.string_cdr(text) == catalog.encode("std_msgs/msg/String",
                                                  catalog.message_class("std_msgs/msg/String")(data=text))
    time = catalog.message_class("builtin_interfaces/msg/Time")(sec=12, nanosec=340_000_000)
    log = catalog.message_class("rcl_interfaces/msg/Log")(stamp=time, level=30, name="move_circle", msg=text,
                                                         file="move_circle.py", function="timer_callback", line=42)
    got = cdr.log_cdr(12_340_000_000, 30, "move_circle", text, "move_circle.py", "timer_callback", 42)
    assert got == catalog.encode("rcl_interfaces/msg/Log", log)


def test_world_log_uses_ros2_severity() -> None:
    line = cdr.world_log_cdr(LogSample(3_000_000_000, "/rosout", 4, "/turtlesim", "Oh no! I hit the wall!"), 0)
    assert ros2_catalog().decode("rcl_interfaces/msg/Log", line).level == 30  # ROS 1 WARN (4) is ROS 2 WARN (30)


def test_log_cdr_rejects_ros1_levels() -> None:
    with pytest.raises(RecordingError, match="10, 20, 30, 40, 50"):
        cdr.log_cdr(0, 2, "/n", "m")


def test_clock_and_twist_cdr_equal_rosbags() -> None:
    catalog = ros2_catalog()
    time = catalog.message_class("builtin_interfaces/msg/Time")(sec=7, nanosec=10_000_000)
    assert cdr.clock_cdr(7_010_000_000) == catalog.encode(
        "rosgraph_msgs/msg/Clock", catalog.message_class("rosgraph_msgs/msg/Clock")(clock=time))
    vector = catalog.message_class("geometry_msgs/msg/Vector3")
    twist = catalog.message_class("geometry_msgs/msg/Twist")(linear=vector(0.26, 0.0, -0.0),
                                                             angular=vector(0.0, 0.0, -1.82))
    assert cdr.twist_cdr((0.26, 0.0, -0.0), (0.0, 0.0, -1.82)) == catalog.encode("geometry_msgs/msg/Twist", twist)


@pytest.mark.parametrize("frame_id", ["", "b", "base", "base_lin", "base_link"])
def test_decode_twist_stamped_reads_every_padding(frame_id: str) -> None:
    catalog = ros2_catalog()
    t = catalog.message_class
    header = t("std_msgs/msg/Header")(stamp=t("builtin_interfaces/msg/Time")(sec=1, nanosec=2), frame_id=frame_id)
    vector = t("geometry_msgs/msg/Vector3")
    stamped = t("geometry_msgs/msg/TwistStamped")(
        header=header, twist=t("geometry_msgs/msg/Twist")(linear=vector(0.1, 0.2, 0.3), angular=vector(-1, -2, 1e-9)))
    data = catalog.encode("geometry_msgs/msg/TwistStamped", stamped)
    assert cdr.decode_twist_stamped_cdr(data) == ((0.1, 0.2, 0.3), (-1.0, -2.0, 1e-9))


def test_decode_twist_cdr_round_trips_and_rejects_wrong_length() -> None:
    data = cdr.twist_cdr((0.5, 0.0, 0.0), (0.0, 0.0, 1.0))
    assert cdr.decode_twist_cdr(data) == ((0.5, 0.0, 0.0), (0.0, 0.0, 1.0))
    with pytest.raises(RecordingError, match="it has 52"):
        cdr.decode_twist_cdr(data[:-1])


def test_decode_odometry_cdr_reads_what_odometry_cdr_wrote(run: Run) -> None:
    for sample in run.odometry[:50]:
        t_ns, pose, linear, angular = cdr.decode_odometry_pose_twist_cdr(cdr.odometry_cdr(sample, 0))
        assert (t_ns, pose, linear, angular) == (sample.t_ns, (*sample.position, *sample.orientation), sample.linear,
                                                 sample.angular)


def test_decode_odometry_cdr_rejects_a_wrong_length(run: Run) -> None:
    data = cdr.odometry_cdr(run.odometry[0], 0)
    for bad in (data[:-1], data + bytes(8), data[:20]):
        with pytest.raises(RecordingError, match="nav_msgs/msg/Odometry"):
            cdr.decode_odometry_pose_twist_cdr(bad)
