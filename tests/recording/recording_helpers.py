"""Recording test helpers: synthetic runs as the world emits them, written through `Recorder`; message builders."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from rosbags.typesys.store import Typestore

from grader.recording import (
    Recorder,
    ground_truth_bytes,
    log_bytes,
    odometry_bytes,
    string_bytes,
    tf_bytes,
    twist_bytes,
)
from sim.samples import GroundTruthSample, OdometrySample, TransformSample

START_NS = 5_000_000_000
BASE_FRAME = "base_footprint"
METADATA = {
    "rosgrade": {
        "rosgrade_version": "0.1.0",
        "mujoco_version": "4.0.0",
        "robot": "turtlebot3_waffle",
        "scenario": {"robot": "turtlebot3_waffle", "initial_pose": {"x": -2.0, "y": -0.5, "yaw": 0.0}},
    }
}


@dataclass(frozen=True)
class Command:
    t_ns: int
    topic: str
    callerid: str
    linear: tuple[float, float, float]
    angular: tuple[float, float, float]


@dataclass(frozen=True)
class LogLine:
    t_ns: int
    level: int
    msg: str


@dataclass
class Run:
    """Everything one synthetic run records."""

    odometry: list[OdometrySample] = field(default_factory=list)
    transforms: list[TransformSample] = field(default_factory=list)
    ground_truth: list[GroundTruthSample] = field(default_factory=list)
    commands: list[Command] = field(default_factory=list)
    logs: list[LogLine] = field(default_factory=list)
    stdout: list[tuple[int, str]] = field(default_factory=list)
    stderr: list[tuple[int, str]] = field(default_factory=list)


def _quat(yaw: float) -> tuple[float, float, float, float]:
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))


def make_run(seconds: float = 2.0, seed: int = 7) -> Run:
    """A robot turning through more than a full circle, with awkward floats (-0.0, tiny, huge) in the mix."""
    rng = np.random.default_rng(seed)
    run = Run()
    for i in range(int(seconds * 30)):
        t_ns = START_NS + i * 33_333_333
        yaw = -3.0 + 6.5 * i / (seconds * 30)
        x, y = float(rng.normal()), float(rng.normal())
        cov = tuple(float(v) for v in rng.normal(size=36))
        twist_cov = (-0.0, 5e-324, 1e300, *(float(v) for v in rng.normal(size=33)))
        pose = ((x, y, 0.0), _quat(yaw))
        twist = ((0.25, -0.0, 0.0), (0.0, 0.0, 1.5))
        run.odometry.append(OdometrySample(t_ns, "/odom", "odom", BASE_FRAME, *pose, *twist, cov, twist_cov))
        run.transforms.append(TransformSample(t_ns, "/tf", "odom", BASE_FRAME, (x, y, 0.0), _quat(yaw)))
    for i in range(int(seconds * 50)):
        t_ns = START_NS + i * 20_000_000
        yaw = math.atan2(math.sin(0.1 * i), math.cos(0.1 * i))
        run.ground_truth.append(
            GroundTruthSample(
                t_ns, "/ground_truth/odom", "world", BASE_FRAME, (float(rng.normal()), float(rng.normal()), 0.01), _quat(yaw), (0.2, 1e-17, 0.0), (0.0, 0.0, -0.7)
            )
        )
    for i in range(int(seconds * 10)):
        t_ns = START_NS + 1_000_000 + i * 100_000_000
        linear, angular = (float(rng.normal()), 0.0, 0.0), (0.0, 0.0, float(rng.normal()))
        run.commands.append(Command(t_ns, "/cmd_vel", "/mover", linear, angular))
    run.commands.append(Command(START_NS + 3_000_000, "/cmd_vel", "/rosgrade_driver", (0.1, 0.0, 0.0), (0.0, 0.0, 0.0)))
    run.logs = [
        LogLine(START_NS + 2_000_000, 2, "Moving forward"),
        LogLine(START_NS + 40_000_000, 8, "Obstacle? ünïcode"),
    ]
    run.stdout = [(START_NS + 1_000_000, "hello"), (START_NS + 60_000_000, "done ✓")]
    run.stderr = [(START_NS + 50_000_000, "Traceback (most recent call last):")]
    return run


def record(path: Path, run: Run, **kwargs: object) -> Path:
    """Write ``run`` the way the runtime does: every output in time order, sim-time stamps, per-topic seq."""
    writes: list[tuple[int, int, str, str, bytes, str]] = []  # (t, order, topic, type, payload, callerid)
    for seq, s in enumerate(run.odometry):
        writes.append((s.t_ns, 0, s.topic, "nav_msgs/Odometry", odometry_bytes(s, seq), "/gazebo"))
    for seq, s in enumerate(run.transforms):
        writes.append((s.t_ns, 1, "/tf", "tf2_msgs/TFMessage", tf_bytes(s, seq), "/gazebo"))
    for seq, s in enumerate(run.ground_truth):
        payload = ground_truth_bytes(s, seq)
        writes.append((s.t_ns, 2, "/ground_truth/odom", "nav_msgs/Odometry", payload, "/gazebo"))
    for c in run.commands:
        writes.append((c.t_ns, 3, c.topic, "geometry_msgs/Twist", twist_bytes(c.linear, c.angular), c.callerid))
    for seq, line in enumerate(run.logs):
        payload = log_bytes(
            line.t_ns, seq, line.level, "/mover", line.msg, "mover.py", "main", 12, ["/cmd_vel", "/rosout"]
        )
        writes.append((line.t_ns, 4, "/rosout", "rosgraph_msgs/Log", payload, "/mover"))
    for t_ns, text in run.stdout:
        writes.append((t_ns, 5, "/rosgrade/stdout", "std_msgs/String", string_bytes(text), "/mover"))
    for t_ns, text in run.stderr:
        writes.append((t_ns, 6, "/rosgrade/stderr", "std_msgs/String", string_bytes(text), "/mover"))
    writes.sort(key=lambda w: (w[0], w[1]))
    with Recorder(path, METADATA, **kwargs) as rec:  # type: ignore[arg-type]
        for t_ns, _, topic, type_name, payload, callerid in writes:
            rec.write(topic, type_name, payload, t_ns, callerid)
        rec.add_metadata("rosgrade.run", {"exit_code": 0, "shutdown_ns": START_NS + 2_000_000_000, "status": "exited"})
    return path


class MessageBuilder:
    """rosbags message objects built field by field from samples (ROS 1 or ROS 2 flavour of the same store API)."""

    def __init__(self, store: Typestore, ros1: bool) -> None:
        self.store, self.ros1 = store, ros1
        self.t = store.types

    def header(self, seq: int, t_ns: int, frame_id: str) -> object:
        stamp = self.t["builtin_interfaces/msg/Time"](sec=t_ns // 1_000_000_000, nanosec=t_ns % 1_000_000_000)
        header = self.t["std_msgs/msg/Header"]
        return header(seq=seq, stamp=stamp, frame_id=frame_id) if self.ros1 else header(stamp=stamp, frame_id=frame_id)

    def vector3(self, v: tuple[float, float, float]) -> object:
        return self.t["geometry_msgs/msg/Vector3"](*v)

    def twist(self, linear: tuple[float, float, float], angular: tuple[float, float, float]) -> object:
        return self.t["geometry_msgs/msg/Twist"](self.vector3(linear), self.vector3(angular))

    def odometry(
        self,
        seq: int,
        frames: tuple[str, str],
        s: OdometrySample | GroundTruthSample,
        pose_cov: tuple[float, ...],
        twist_cov: tuple[float, ...],
    ) -> object:
        t = self.t
        point, quaternion = t["geometry_msgs/msg/Point"](*s.position), t["geometry_msgs/msg/Quaternion"](*s.orientation)
        pose = t["geometry_msgs/msg/Pose"](point, quaternion)
        twist = self.twist(s.linear, s.angular)
        return t["nav_msgs/msg/Odometry"](
            self.header(seq, s.t_ns, frames[0]),
            frames[1],
            t["geometry_msgs/msg/PoseWithCovariance"](pose, np.array(pose_cov, dtype=np.float64)),
            t["geometry_msgs/msg/TwistWithCovariance"](twist, np.array(twist_cov, dtype=np.float64)),
        )

    def from_odometry_sample(self, s: OdometrySample, seq: int) -> object:
        return self.odometry(seq, (s.frame_id, s.child_frame_id), s, s.pose_covariance, s.twist_covariance)

    def from_ground_truth_sample(self, s: GroundTruthSample, seq: int) -> object:
        zero = (0.0,) * 36
        return self.odometry(seq, ("world", BASE_FRAME), s, zero, zero)

    def from_transform_sample(self, s: TransformSample, seq: int) -> object:
        t = self.t
        rotation = t["geometry_msgs/msg/Quaternion"](*s.rotation)
        transform = t["geometry_msgs/msg/Transform"](self.vector3(s.translation), rotation)
        header = self.header(seq, s.t_ns, s.frame_id)
        stamped = t["geometry_msgs/msg/TransformStamped"](header, s.child_frame_id, transform)
        return t["tf2_msgs/msg/TFMessage"]([stamped])

    def serialize(self, msg: object) -> bytes:
        typename = msg.__msgtype__  # type: ignore[attr-defined]
        return bytes(self.store.serialize_ros1(msg, typename) if self.ros1 else self.store.serialize_cdr(msg, typename))
