"""rospy's exception classes, with real rospy's hierarchy (ROSInterruptException is also a KeyboardInterrupt)."""
from __future__ import annotations


class ROSException(Exception):
    """Base exception class for ROS clients."""


class ROSSerializationException(ROSException):
    """A message could not be serialized (a field has the wrong type)."""


class ROSInitException(ROSException):
    """The node is not initialized, or could not be."""


class ROSInterruptException(ROSException, KeyboardInterrupt):
    """A blocking call was interrupted by shutdown; ``except KeyboardInterrupt`` catches it too, as in rospy."""


class ROSTimeMovedBackwardsException(ROSInterruptException):
    """ROS time jumped backwards during a sleep; ``time`` is the size of the jump in seconds."""

    def __init__(self, time: float) -> None:
        self.time = time
        super().__init__("ROS time moved backwards")


class ROSInternalException(Exception):
    """Base class for errors internal to the client library."""
