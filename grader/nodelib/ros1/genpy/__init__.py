"""rosgrade's genpy: the ROS 1 Python message runtime (Message, Time, Duration) with genpy 0.6.16's behaviour."""
from __future__ import annotations

from .message import DeserializationError, Message, MessageException, SerializationError, struct_I
from .rostime import Duration, Time, TVal

__all__ = ["DeserializationError", "Duration", "Message", "MessageException", "SerializationError", "TVal",
           "Time", "struct_I"]
