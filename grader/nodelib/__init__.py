"""What student nodes import instead of a ROS install: ``common/`` (the channel, scheduler, time patches, bootstrap)
plus one client library's root, ``ros1/`` (rospy, genpy, messages, tf) or ``ros2/`` (rclpy, rosidl messages)."""
from __future__ import annotations

import compileall
import functools
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


@functools.cache
def precompile() -> None:
    """Write the client libraries' bytecode beside them, once per process, where this user may write there.

    Nodes run with ``-B``: they never write into the grader's files. So without this, every node of an editable
    install (``pip install -e``; pip compiles a normal one) compiles rospy and its messages from source again,
    some 25 ms of each node's start. Checking that the bytecode is current costs about 15 ms.
    """
    compileall.compile_dir(NODELIB, quiet=2, workers=1)
