"""CDR (ROS 2) bytes of the messages the grader emits, and decoders for the commands it reads: serialize.py's twin.

Little-endian CDR with the 4-byte encapsulation header, as rosbag2 and rclpy write it: each primitive is aligned
to its own size counted from the end of that header, a string is a uint32 length that counts its NUL, then the
bytes and the NUL. The tests compare every function here with rosbags' ``serialize_cdr`` byte for byte.
"""
from __future__ import annotations

import struct
from collections.abc import Sequence
from typing import TYPE_CHECKING

from grader.recording.errors import RecordingError

if TYPE_CHECKING:
    from sim.samples import (ColorSample, GroundTruthSample, ImuSample, JointStateSample, LogSample, OdometrySample,
                             ScanSample, TransformSample, TurtlePoseSample, Vec3)

ENCAPSULATION = b"\x00\x01\x00\x00"  # CDR, little-endian, no options
_NS = 1_000_000_000
_I32_U32 = struct.Struct("<iI")
_U32 = struct.Struct("<I")
_ZERO_COVARIANCE = (0.0,) * 36
_ZERO_COVARIANCE_3 = (0.0,) * 9
# ROS 2 severities (rcl_interfaces/msg/Log) for the ROS 1 levels the worlds log with.
LEVEL_FROM_ROS1 = {1: 10, 2: 20, 4: 30, 8: 40, 16: 50}
ROS2_LEVELS = frozenset(LEVEL_FROM_ROS1.values())


class _Writer:
    """Appends CDR fields with their alignment; positions count from after the encapsulation header."""

    __slots__ = ("parts", "size")

    def __init__(self) -> None:
        self.parts: list[bytes] = [ENCAPSULATION]
        self.size = 0

    def _align(self, n: int) -> None:
        pad = -self.size % n
        if pad:
            self.parts.append(bytes(pad))
            self.size += pad

    def raw(self, data: bytes, align: int) -> None:
        self._align(align)
        self.parts.append(data)
        self.size += len(data)

    def u32(self, value: int) -> None:
        self.raw(_U32.pack(value), 4)

    def stamp(self, t_ns: int) -> None:
        """builtin_interfaces/Time: int32 sec, uint32 nanosec."""
        self.raw(_I32_U32.pack(*divmod(t_ns, _NS)), 4)

    def string(self, text: str) -> None:
        data = text.encode() + b"\x00"
        self.u32(len(data))
        self.parts.append(data)
        self.size += len(data)

    def header(self, t_ns: int, frame_id: str) -> None:
        self.stamp(t_ns)
        self.string(frame_id)

    def f64(self, values: Sequence[float]) -> None:
        self.raw(struct.pack(f"<{len(values)}d", *values), 8)

    def f32(self, values: Sequence[float]) -> None:
        self.raw(struct.pack(f"<{len(values)}f", *values), 4)

    def bytes(self) -> bytes:
        return b"".join(self.parts)


def _checked(type_name: str, build) -> bytes:
    try:
        return build()
    except (struct.error, OverflowError, UnicodeEncodeError) as exc:
        raise RecordingError(f"cannot serialize {type_name}: {exc}") from None


def _odometry(t_ns: int, frame_id: str, child: str, pose: Sequence[float], pose_cov: Sequence[float],
              twist: Sequence[float], twist_cov: Sequence[float]) -> bytes:
    if len(pose_cov) != 36 or len(twist_cov) != 36:
        raise RecordingError("an Odometry covariance needs 36 values")

    def build() -> bytes:
        w = _Writer()
        w.header(t_ns, frame_id)
        w.string(child)
        w.f64((*pose, *pose_cov, *twist, *twist_cov))
        return w.bytes()
    return _checked("nav_msgs/msg/Odometry", build)


def odometry_cdr(sample: OdometrySample, seq: int) -> bytes:  # noqa: ARG001 -- a ROS 2 Header has no seq
    """nav_msgs/msg/Odometry of what the robot publishes on its odometry topic."""
    return _odometry(sample.t_ns, sample.frame_id, sample.child_frame_id, (*sample.position, *sample.orientation),
                     sample.pose_covariance, (*sample.linear, *sample.angular), sample.twist_covariance)


def ground_truth_cdr(sample: GroundTruthSample, seq: int) -> bytes:  # noqa: ARG001
    """nav_msgs/msg/Odometry of the true world pose and body twist (zero covariance)."""
    return _odometry(sample.t_ns, sample.frame_id, sample.child_frame_id, (*sample.position, *sample.orientation),
                     _ZERO_COVARIANCE, (*sample.linear, *sample.angular), _ZERO_COVARIANCE)


def tf_cdr(sample: TransformSample, seq: int) -> bytes:  # noqa: ARG001
    """tf2_msgs/msg/TFMessage holding one geometry_msgs/msg/TransformStamped."""
    def build() -> bytes:
        w = _Writer()
        w.u32(1)
        w.header(sample.t_ns, sample.frame_id)
        w.string(sample.child_frame_id)
        w.f64((*sample.translation, *sample.rotation))
        return w.bytes()
    return _checked("tf2_msgs/msg/TFMessage", build)


def imu_cdr(sample: ImuSample, seq: int) -> bytes:  # noqa: ARG001
    """sensor_msgs/msg/Imu with zero covariances."""
    def build() -> bytes:
        w = _Writer()
        w.header(sample.t_ns, sample.frame_id)
        w.f64((*sample.orientation, *_ZERO_COVARIANCE_3, *sample.angular_velocity, *_ZERO_COVARIANCE_3,
               *sample.linear_acceleration, *_ZERO_COVARIANCE_3))
        return w.bytes()
    return _checked("sensor_msgs/msg/Imu", build)


def joint_state_cdr(sample: JointStateSample, seq: int) -> bytes:  # noqa: ARG001
    """sensor_msgs/msg/JointState: names and positions, velocities if given, no efforts."""
    def build() -> bytes:
        w = _Writer()
        w.header(sample.t_ns, sample.frame_id)
        w.u32(len(sample.names))
        for name in sample.names:
            w.string(name)
        for values in (sample.positions, sample.velocities):
            w.u32(len(values))
            if values:
                w.f64(values)
        w.u32(0)
        return w.bytes()
    return _checked("sensor_msgs/msg/JointState", build)


def laser_scan_cdr(sample: ScanSample, seq: int) -> bytes:  # noqa: ARG001
    """sensor_msgs/msg/LaserScan as Gazebo's plugin fills it (see serialize.laser_scan_bytes)."""
    def build() -> bytes:
        n = len(sample.ranges)
        w = _Writer()
        w.header(sample.t_ns, sample.frame_id)
        w.f32((sample.angle_min, sample.angle_max, sample.angle_increment, 0.0, 0.0, sample.range_min,
               sample.range_max))
        w.u32(n)
        if n:
            w.f32(sample.ranges)
        w.u32(n)
        if n:
            w.raw(bytes(4 * n), 4)
        return w.bytes()
    return _checked("sensor_msgs/msg/LaserScan", build)


def turtle_pose_cdr(sample: TurtlePoseSample, seq: int) -> bytes:  # noqa: ARG001
    """turtlesim/msg/Pose."""
    def build() -> bytes:
        w = _Writer()
        w.f32((sample.x, sample.y, sample.theta, sample.linear_velocity, sample.angular_velocity))
        return w.bytes()
    return _checked("turtlesim/msg/Pose", build)


def color_cdr(sample: ColorSample, seq: int) -> bytes:  # noqa: ARG001
    """turtlesim/msg/Color."""
    return _checked("turtlesim/msg/Color", lambda: ENCAPSULATION + bytes((sample.r, sample.g, sample.b)))


def twist_cdr(linear: Vec3, angular: Vec3) -> bytes:
    """geometry_msgs/msg/Twist."""
    def build() -> bytes:
        w = _Writer()
        w.f64((*linear, *angular))
        return w.bytes()
    return _checked("geometry_msgs/msg/Twist", build)


def string_cdr(text: str) -> bytes:
    """std_msgs/msg/String."""
    def build() -> bytes:
        w = _Writer()
        w.string(text)
        return w.bytes()
    return _checked("std_msgs/msg/String", build)


def clock_cdr(t_ns: int) -> bytes:
    """rosgraph_msgs/msg/Clock."""
    return _checked("rosgraph_msgs/msg/Clock", lambda: ENCAPSULATION + _I32_U32.pack(*divmod(t_ns, _NS)))


def log_cdr(t_ns: int, level: int, name: str, msg: str, file: str = "", function: str = "", line: int = 0) -> bytes:
    """rcl_interfaces/msg/Log (a /rosout line); level is 10 DEBUG, 20 INFO, 30 WARN, 40 ERROR or 50 FATAL."""
    if level not in ROS2_LEVELS:
        raise RecordingError(f"log level {level!r} is not one of 10, 20, 30, 40, 50")

    def build() -> bytes:
        w = _Writer()
        w.stamp(t_ns)
        w.raw(bytes((level,)), 1)
        for text in (name, msg, file, function):
            w.string(text)
        w.u32(line)
        return w.bytes()
    return _checked("rcl_interfaces/msg/Log", build)


def world_log_cdr(sample: LogSample, seq: int) -> bytes:  # noqa: ARG001
    """rcl_interfaces/msg/Log of a line the world itself logs (worlds log with ROS 1 levels)."""
    return log_cdr(sample.t_ns, LEVEL_FROM_ROS1[sample.level], sample.name, sample.msg)


_TWIST_CDR = struct.Struct("<4x6d")
_STAMPED_HEAD = struct.Struct("<4xiII")  # encapsulation, stamp sec and nanosec, frame_id length


def decode_twist_cdr(data: bytes | bytearray | memoryview) -> tuple[Vec3, Vec3]:
    """(linear, angular) of geometry_msgs/msg/Twist CDR bytes; RecordingError unless exactly 52 bytes."""
    if len(data) != _TWIST_CDR.size or bytes(data[:4]) != ENCAPSULATION:
        raise RecordingError(f"{len(data)} bytes are not a geometry_msgs/msg/Twist message (it has 52)")
    v = _TWIST_CDR.unpack(data)
    return (v[0], v[1], v[2]), (v[3], v[4], v[5])


def _aligned(pos: int, size: int) -> int:
    """``pos`` moved up to the next multiple of ``size`` counted from the CDR body, which starts after the 4-byte
    encapsulation header: where the field after a string lies."""
    return pos + (-(pos - 4) % size)


def decode_twist_stamped_cdr(data: bytes | bytearray | memoryview) -> tuple[Vec3, Vec3]:
    """(linear, angular) of geometry_msgs/msg/TwistStamped CDR bytes (the node link has already validated them)."""
    try:
        _, _, length = _STAMPED_HEAD.unpack_from(data, 0)
        v = struct.unpack_from("<6d", data, _aligned(16 + length, 8))
    except struct.error:
        raise RecordingError(f"{len(data)} bytes are not a geometry_msgs/msg/TwistStamped message") from None
    return (v[0], v[1], v[2]), (v[3], v[4], v[5])


_ODOMETRY_HEAD = struct.Struct("<4xiII")  # encapsulation, stamp sec and nanosec, frame_id length
_ODOMETRY_BODY = struct.Struct("<85d")  # pose 7 + covariance 36 + twist 6 + covariance 36


def decode_odometry_pose_twist_cdr(data: bytes | bytearray | memoryview) -> tuple[int, tuple[float, ...], Vec3, Vec3]:
    """(stamp ns, pose x y z qx qy qz qw, linear, angular) of nav_msgs/msg/Odometry CDR bytes, checking the exact
    length (serialize.decode_odometry_pose_twist's twin)."""
    try:
        sec, nanosec, length = _ODOMETRY_HEAD.unpack_from(data, 0)
        pos = _aligned(16 + length, 4)
        (child,) = _U32.unpack_from(data, pos)
        pos = _aligned(pos + 4 + child, 8)
        if pos + _ODOMETRY_BODY.size != len(data):
            raise struct.error("length")
        v = _ODOMETRY_BODY.unpack_from(data, pos)
    except struct.error:
        raise RecordingError(f"{len(data)} bytes are not a nav_msgs/msg/Odometry message") from None
    return sec * _NS + nanosec, v[0:7], (v[43], v[44], v[45]), (v[46], v[47], v[48])
