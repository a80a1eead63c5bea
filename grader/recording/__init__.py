"""Recording a run to MCAP and reading recordings (ours, ROS 1 bags, ROS 2 bags) back as arrays for scoring."""
from __future__ import annotations

from grader.recording.errors import RecordingError
from grader.recording.messages import MessageCatalog, default_catalog
from grader.recording.reader import Recording
from grader.recording.serialize import (
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
from grader.recording.series import CommandSeries, LogLine, OutputLine, TimeSeries, TopicInfo, TransformSeries
from grader.recording.writer import Recorder

__all__ = [
    "CommandSeries",
    "LogLine",
    "MessageCatalog",
    "OutputLine",
    "Recorder",
    "Recording",
    "RecordingError",
    "TimeSeries",
    "TopicInfo",
    "TransformSeries",
    "clock_bytes",
    "decode_odometry_pose_twist",
    "decode_twist",
    "default_catalog",
    "ground_truth_bytes",
    "imu_bytes",
    "joint_state_bytes",
    "laser_scan_bytes",
    "log_bytes",
    "odometry_bytes",
    "string_bytes",
    "tf_bytes",
    "twist_bytes",
]
