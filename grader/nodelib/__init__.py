"""What student nodes import instead of a ROS install: ``common/`` (the channel, scheduler, time patches, bootstrap)
plus one client library's root, ``ros1/`` (rospy, genpy, messages, tf) or ``ros2/`` (rclpy, rosidl messages)."""
from __future__ import annotations

import os
from pathlib import Path

NODELIB = Path(__file__).resolve().parent
COMMON = NODELIB / "common"
FLAVOURS = ("ros1", "ros2")


def import_roots(flavour: str) -> list[Path]:
    """The folders a node of this client library flavour has on its import path, first first."""
    if flavour not in FLAVOURS:
        raise ValueError(f"unknown client library flavour {flavour!r}: expected one of {', '.join(FLAVOURS)}")
    return [COMMON, NODELIB / flavour]


def pythonpath(flavour: str) -> str:
    """PYTHONPATH for a node of this flavour."""
    return os.pathsep.join(str(p) for p in import_roots(flavour))
