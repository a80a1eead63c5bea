"""ROS 1 bytes of the samples a world publishes: the one place the session turns world values into wire messages."""
from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping

from grader.recording.serialize import (color_bytes, ground_truth_bytes, imu_bytes, joint_state_bytes,
                                        laser_scan_bytes, odometry_bytes, tf_bytes, turtle_pose_bytes, world_log_bytes)
from grader.recording import MessageCatalog
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


def request_values(catalog: MessageCatalog, srv_type: str, data: bytes) -> dict[str, object]:
    """The fields of a ``srv_type`` request (ROS 1 bytes the node link has already checked) as plain values."""
    message = catalog.decode(srv_type + "Request", data)
    return {f.name: getattr(message, f.name) for f in dataclasses.fields(message) if not f.name.startswith("__")}


def response_bytes(catalog: MessageCatalog, srv_type: str, values: Mapping[str, object]) -> bytes:
    """The ROS 1 bytes of a ``srv_type`` response built from a world's plain values."""
    type_name = srv_type + "Response"
    return catalog.encode(type_name, catalog.message_class(type_name)(**values))
