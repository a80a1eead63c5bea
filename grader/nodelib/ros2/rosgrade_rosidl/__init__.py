"""rosgrade's ROS 2 message runtime: rosidl-like message classes and their CDR encoding, stdlib and numpy only.

Contract with rclpy: ``serialize(msg)`` gives CDR little-endian bytes with the 4-byte encapsulation header, as rosbags'
``serialize_cdr``; ``deserialize(cls, data)`` is its inverse (trailing padding ignored) and raises DecodeError on malformed bytes;
``type_name``/``type_hash`` give "geometry_msgs/msg/Twist" and its Jazzy RIHS01 hash.
"""
from __future__ import annotations

import struct
from typing import Any

from . import _cdr
from ._cdr import HEADER, DecodeError
from ._classes import action_class, message_class, service_class
from ._convert import FieldConversionError
from ._defs import SERVICES
from ._extra import ACTIONS
from ._model import UnknownType, spec

__all__ = ["DecodeError", "FieldConversionError", "UnknownType", "action_class", "deserialize", "message_class",
           "serialize", "service_class", "type_hash", "type_name"]

_encoders: dict[type, Any] = {}
_decoders: dict[type, Any] = {}


def type_name(msg_or_cls: Any) -> str:
    """'geometry_msgs/msg/Twist' for a message (or service) class or instance of this runtime."""
    cls = msg_or_cls if isinstance(msg_or_cls, type) else type(msg_or_cls)
    name = getattr(type(cls), "_rosgrade_type", None)
    if name is None:
        raise UnknownType(f"{cls.__module__}.{cls.__qualname__} is not a rosgrade ROS 2 interface class")
    return name


def type_hash(msg_or_cls: Any) -> str:
    """The type's Jazzy RIHS01 hash, 'RIHS01_<64 hex>'."""
    name = type_name(msg_or_cls)
    if name in ACTIONS:
        return ACTIONS[name]
    return SERVICES[name] if name in SERVICES else spec(name).hash


def serialize(msg: Any) -> bytes:
    """CDR bytes of ``msg`` (with the encapsulation header), converting fields as rosidl's C code does."""
    cls = type(msg)
    encode = _encoders.get(cls)
    if encode is None:
        encode = _encoders[cls] = _cdr.encoder(type_name(cls))
    body = bytearray()
    encode(msg, body)
    return HEADER + body


def deserialize(cls: type, data: bytes | bytearray | memoryview) -> Any:
    """The ``cls`` message in CDR ``data``; DecodeError when the bytes end before the message does or are malformed."""
    decode = _decoders.get(cls)
    if decode is None:
        decode = _decoders[cls] = _cdr.decoder(type_name(cls))
    view = memoryview(data).cast("B") if not isinstance(data, bytes) else data
    if len(view) < 4 or view[0] != 0 or view[1] != 1:
        raise DecodeError(f"{len(view)} bytes do not start with the CDR little-endian header 00 01")
    body = view[4:]
    try:
        msg, _ = decode(body, 0)
    except DecodeError:
        raise
    except struct.error:
        raise DecodeError(f"{len(view)} bytes are not a valid {type_name(cls)}: the data ends inside the message"
                          ) from None
    except (ValueError, IndexError, OverflowError, MemoryError) as exc:
        raise DecodeError(f"{len(view)} bytes are not a valid {type_name(cls)}: {exc}") from None
    return msg  # bytes after the message are ignored, as Fast DDS pads (with junk) past the end
