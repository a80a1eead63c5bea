"""The names rclpy's C extension exports that student code meets: RCLError (tracebacks show this class path),
NodeNameNonExistentError, InvalidHandle and SignalHandlerOptions."""
from __future__ import annotations

from enum import IntEnum


class RCLError(RuntimeError):
    """An rcl call failed (raised by real rclpy's pybind11 extension with rcl's error text)."""


class NodeNameNonExistentError(RCLError):
    """A graph query by node named a node the graph does not hold."""


class InvalidHandle(Exception):
    """An entity was used after its destruction was requested."""


class SignalHandlerOptions(IntEnum):
    """Which signal handlers rclpy.init installs."""

    NO = 0
    SIGINT = 1
    SIGTERM = 2
    ALL = 3


# rcl's error texts as Jazzy's rclpy (the PyPI ros-jazzy-* wheels, built under /project) prints them.
PUBLISHER_CONTEXT_INVALID = "publisher's context is invalid, at /project/src/rcl/publisher.c:423"
CONTEXT_INVALID = ("the given context is not valid, either rcl_init() was not called or rcl_shutdown() was called., "
                   "at /project/src/rcl/guard_condition.c:67")
ROSOUT_FINI_FAILED = ("Failed to fini rosout publisher: rcl node implementation is invalid, "
                      "at /project/src/rcl/node.c:390")
DESTROYED = "cannot use Destroyable because destruction was requested"
ALREADY_SHUT_DOWN = ("failed to shutdown: rcl_shutdown already called on the given context, "
                     "at /project/src/rcl/init.c:333")
