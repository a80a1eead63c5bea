"""The struct serializers give exactly rosbags' serialize_ros1 bytes; the fast decoders read them back exactly."""
from __future__ import annotations

import math
import struct

import numpy as np
import pytest

from recording_helpers import BASE_FRAME, MessageBuilder, Run
from grader.recording import (
    RecordingError,
    clock_bytes,
    decode_odometry_pose_twist,
    decode_twist,
    ground_truth_bytes,
    imu_bytes,
    joint_state_bytes,
    laser_scan_bytes,
    log_bytes,
    odometry_bytes,
    string_bytes,
    tf_bytes,
    twist_bytes,
)
from sim.samples import ImuSample, JointStateSample, OdometrySample, ScanSample


def test_odometry_bytes_equal_rosbags(run: Run, ros1_msgs: MessageBuilder) -> None:
    for seq, sample in enumerate(run.odometry):
        assert odometry_bytes(sample, seq) == ros1_msgs.serialize(ros1_msgs.from_odometry_sample(sample, seq))


def test_ground_truth_bytes_equal_rosbags(run: Run, ros1_msgs: MessageBuilder) -> None:
    for seq, sample in enumerate(run.ground_truth):
        expected = ros1_msgs.serialize(ros1_msgs.from_ground_truth_sample(sample, seq))
        assert ground_truth_bytes(sample, seq) == expected


def test_tf_bytes_equal_rosbags(run: Run, ros1_msgs: MessageBuilder) -> None:
    for seq, sample in enumerate(run.transforms):
        assert tf_bytes(sample, seq) == ros1_msgs.serialize(ros1_msgs.from_transform_sample(sample, seq))


def test_imu_bytes_equal_rosbags(ros1_msgs: MessageBuilder) -> None:
    sample = ImuSample(5_000_000_001, "/imu", "imu_link", (0.0, -0.0, 0.38, 0.92), (1e-300, 0.0, -1.82),
                       (0.01, -0.2, 9.81))
    t = ros1_msgs.t
    zero = np.zeros(9)
    expected = t["sensor_msgs/msg/Imu"](ros1_msgs.header(3, sample.t_ns, "imu_link"),
                                         t["geometry_msgs/msg/Quaternion"](*sample.orientation), zero,
                                         ros1_msgs.vector3(sample.angular_velocity), zero,
                                         ros1_msgs.vector3(sample.linear_acceleration), zero)
    assert imu_bytes(sample, 3) == ros1_msgs.serialize(expected)


@pytest.mark.parametrize("velocities", [(), (1.5, -2.25, 0.0, 1e-9)])
def test_joint_state_bytes_equal_rosbags(ros1_msgs: MessageBuilder, velocities: tuple[float, ...]) -> None:
    names = ("front_left_wheel", "front_right_wheel", "rear_left_wheel", "rear_right_wheel")
    sample = JointStateSample(7_000_000_000, "/joint_states", "", names, (0.5, -0.5, 0.5, 123.25), velocities)
    expected = ros1_msgs.t["sensor_msgs/msg/JointState"](
        ros1_msgs.header(0, sample.t_ns, ""), list(names), np.array(sample.positions), np.array(velocities),
        np.zeros(0))
    assert joint_state_bytes(sample, 0) == ros1_msgs.serialize(expected)


def test_laser_scan_bytes_equal_rosbags(ros1_msgs: MessageBuilder) -> None:
    ranges = tuple([math.inf] * 358 + [0.5, 3.5])
    sample = ScanSample(9_200_000_000, "/scan", "base_scan", 0.0, 6.28319, 6.28319 / 359, 0.12, 3.5, ranges)
    expected = ros1_msgs.t["sensor_msgs/msg/LaserScan"](
        ros1_msgs.header(12, sample.t_ns, "base_scan"), 0.0, 6.28319, 6.28319 / 359, 0.0, 0.0, 0.12, 3.5,
        np.array(ranges, dtype=np.float32), np.zeros(360, dtype=np.float32))
    assert laser_scan_bytes(sample, 12) == ros1_msgs.serialize(expected)


@pytest.mark.parametrize(
    "linear,angular",
    [((0.0, 0.0, 0.0), (0.0, 0.0, 0.0)), ((0.26, -0.0, 1e-300), (math.inf, -math.inf, -1.82))],
)
def test_twist_bytes_equal_rosbags(ros1_msgs: MessageBuilder, linear, angular) -> None:  # noqa: ANN001
    assert twist_bytes(linear, angular) == ros1_msgs.serialize(ros1_msgs.twist(linear, angular))


@pytest.mark.parametrize("text", ["", "hello", "ünïcode ✓\nsecond line", "x" * 10_000])
def test_string_bytes_equal_rosbags(ros1_msgs: MessageBuilder, text: str) -> None:
    assert string_bytes(text) == ros1_msgs.serialize(ros1_msgs.t["std_msgs/msg/String"](text))


@pytest.mark.parametrize("t_ns", [0, 1, 5_000_000_000, 2_147_483_647_999_999_999])  # rosbags packs secs as int32
def test_clock_bytes_equal_rosbags(ros1_msgs: MessageBuilder, t_ns: int) -> None:
    t = ros1_msgs.t
    clock = t["rosgraph_msgs/msg/Clock"](t["builtin_interfaces/msg/Time"](sec=t_ns // 10**9, nanosec=t_ns % 10**9))
    assert clock_bytes(t_ns) == ros1_msgs.serialize(clock)


def test_clock_secs_are_unsigned_like_ros1() -> None:
    assert clock_bytes(4_294_967_295_999_999_999) == struct.pack("<II", 0xFFFFFFFF, 999_999_999)
    with pytest.raises(RecordingError, match="does not fit"):
        clock_bytes(4_294_967_296_000_000_000)


@pytest.mark.parametrize("level", [1, 2, 4, 8, 16])
@pytest.mark.parametrize("topics", [(), ("/cmd_vel",), ("/cmd_vel", "/rosout")])
def test_log_bytes_equal_rosbags(ros1_msgs: MessageBuilder, level: int, topics: tuple[str, ...]) -> None:
    t_ns, seq = 7_123_456_789, 3
    expected = ros1_msgs.t["rosgraph_msgs/msg/Log"](
        ros1_msgs.header(seq, t_ns, ""), level, "/mover", "ünïcode msg", "mover.py", "<module>", 42, list(topics)
    )
    got = log_bytes(t_ns, seq, level, "/mover", "ünïcode msg", "mover.py", "<module>", 42, topics)
    assert got == ros1_msgs.serialize(expected)


def test_log_bytes_rejects_unknown_level() -> None:
    with pytest.raises(RecordingError, match="log level 3"):
        log_bytes(0, 0, 3, "/n", "m")


def test_negative_time_is_rejected(run: Run) -> None:
    with pytest.raises(RecordingError, match="does not fit a ROS 1 time stamp"):
        clock_bytes(-1)
    sample = run.odometry[0]
    with pytest.raises(RecordingError, match="does not fit"):
        odometry_bytes(OdometrySample(**{**_fields(sample), "t_ns": -5}), 0)


def test_odometry_covariance_must_have_36_values(run: Run) -> None:
    sample = OdometrySample(**{**_fields(run.odometry[0]), "pose_covariance": (0.0,) * 35})
    with pytest.raises(RecordingError, match="36 values"):
        odometry_bytes(sample, 0)


def test_seq_out_of_range_is_an_error(run: Run) -> None:
    with pytest.raises(RecordingError, match="cannot serialize nav_msgs/Odometry"):
        odometry_bytes(run.odometry[0], 2**32)


def test_twist_with_wrong_arity_is_an_error() -> None:
    with pytest.raises(RecordingError, match="cannot serialize geometry_msgs/Twist"):
        twist_bytes((1.0, 2.0), (0.0, 0.0, 0.0))  # type: ignore[arg-type]


def test_decode_twist_round_trips_bit_exact() -> None:
    linear, angular = (0.1, -0.0, 5e-324), (math.pi, 0.0, -1.82)
    got = decode_twist(twist_bytes(linear, angular))
    assert struct.pack("<6d", *got[0], *got[1]) == struct.pack("<6d", *linear, *angular)


@pytest.mark.parametrize("size", [0, 47, 49])
def test_decode_twist_rejects_wrong_length(size: int) -> None:
    with pytest.raises(RecordingError, match=f"{size} bytes are not a geometry_msgs/Twist"):
        decode_twist(bytes(size))


def test_decode_odometry_reads_stamp_pose_and_twist(run: Run) -> None:
    sample = run.odometry[5]
    t_ns, pose, linear, angular = decode_odometry_pose_twist(odometry_bytes(sample, 5))
    assert t_ns == sample.t_ns
    assert pose == (*sample.position, *sample.orientation)
    assert (linear, angular) == (sample.linear, sample.angular)


@pytest.mark.parametrize("cut", [1, 11, 20, 100])
def test_decode_odometry_rejects_truncated(run: Run, cut: int) -> None:
    data = odometry_bytes(run.odometry[0], 0)
    with pytest.raises(RecordingError, match="not a nav_msgs/Odometry"):
        decode_odometry_pose_twist(data[:-cut])


def test_decode_odometry_rejects_trailing_bytes(run: Run) -> None:
    with pytest.raises(RecordingError, match="wrong length"):
        decode_odometry_pose_twist(odometry_bytes(run.odometry[0], 0) + b"\0")


def _fields(sample: OdometrySample) -> dict[str, object]:
    return {name: getattr(sample, name) for name in OdometrySample.__slots__}


def test_ground_truth_frames_come_from_the_sample(run: Run) -> None:
    data = ground_truth_bytes(run.ground_truth[0], 0)
    frame = BASE_FRAME.encode()
    assert data[12:12 + 13 + len(frame)] == b"\x05\0\0\0world" + struct.pack("<I", len(frame)) + frame
