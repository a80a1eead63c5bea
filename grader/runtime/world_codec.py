"""ROS 1 bytes of the samples a world publishes: the one place the session turns world values into wire messages."""
from __future__ import annotations

from collections.abc import Callable

from grader.recording.serialize import (color_bytes, ground_truth_bytes, imu_bytes, joint_state_bytes,
                                        laser_scan_bytes, odometry_bytes, tf_bytes, turtle_pose_bytes, world_log_bytes)
from sim.samples import (ColorSample, GroundTruthSample, ImuSample, JointStateSample, LogSample, OdometrySample,
                         ScanSample, TransformSample, TurtlePoseSample)


class WorldCodecError(Exception):
    """A world produced a sample of a kind this codec cannot encode."""


_ENCODERS: dict[type, Callable[..., bytes]] = {
    OdometrySample: odometry_bytes,
    TransformSample: tf_bytes,
    GroundTruthSample: ground_truth_bytes,
    ImuSample: imu_bytes,
    JointStateSample: joint_state_bytes,
    ScanSample: laser_scan_bytes,
    TurtlePoseSample: turtle_pose_bytes,
    ColorSample: color_bytes,
    LogSample: world_log_bytes,
}


def encode(sample: object, seq: int) -> bytes:
    """The ROS 1 message bytes of one world sample, with header sequence number ``seq``."""
    try:
        encoder = _ENCODERS[type(sample)]
    except KeyError:
        raise WorldCodecError(f"no ROS 1 encoding for a world sample of type {type(sample).__name__}") from None
    return encoder(sample, seq)
