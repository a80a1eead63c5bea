"""Deterministic random field values for any rosidl-like message class, read from ``_fields_and_field_types`` only.

Shared by the CDR battery (ours vs rosbags) and the serialization probes (ours vs real rclpy); stdlib + numpy.
"""
from __future__ import annotations

import array
import importlib
import random
import re
import struct

import numpy

STRINGS = ["", "odom", "base_link", "h\u00e9llo \u00fcnic\u00f6de \u2713 \U0001f600", "x" * 300]
INT_RANGES = {"int8": (-128, 127), "uint8": (0, 255), "int16": (-32768, 32767), "uint16": (0, 65535),
              "int32": (-2 ** 31, 2 ** 31 - 1), "uint32": (0, 2 ** 32 - 1), "int64": (-2 ** 63, 2 ** 63 - 1),
              "uint64": (0, 2 ** 64 - 1)}
TYPECODES = {"float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H", "int32": "i",
             "uint32": "I", "int64": "q", "uint64": "Q"}
_TEXT = re.compile(r"^(?:sequence<(?P<seq>[^,>]+)(?:, (?P<bound>\d+))?>|(?P<arr>[^\[]+)\[(?P<size>\d+)\]|(?P<one>.+))$")


def message_class(short: str) -> type:
    """'geometry_msgs/Point' -> the class."""
    package, name = short.split("/")
    base, _, part = name.rpartition("_")
    action, _, service = base.rpartition("_")
    if service in _ACTION_SERVICES:  # an action's service's message, reached through the action's Impl
        return getattr(getattr(_action(package, action).Impl, _ACTION_SERVICES[service]), part)
    if part in ("Request", "Response", "Event"):  # a service's message, reached through its service class
        return getattr(getattr(importlib.import_module(f"{package}.srv"), base), part)
    if part == "FeedbackMessage":
        return _action(package, base).Impl.FeedbackMessage
    if part in ("Goal", "Result", "Feedback"):
        return getattr(_action(package, base), part)
    return getattr(importlib.import_module(f"{package}.msg"), name)


_ACTION_SERVICES = {"SendGoal": "SendGoalService", "GetResult": "GetResultService"}


def _action(package: str, name: str) -> type:
    return getattr(importlib.import_module(f"{package}.action"), name)


def scalar(rng: random.Random, element: str) -> object:
    if element == "double":
        return rng.choice([0.0, 1.5, -2.25e-3, 1e300, -0.0, rng.uniform(-1e6, 1e6)])
    if element == "float":
        return struct.unpack("<f", struct.pack("<f", rng.choice([0.0, 0.5, -3.75, rng.uniform(-1e3, 1e3)])))[0]
    if element in INT_RANGES:
        low, high = INT_RANGES[element]
        return rng.choice([low, high, 0, rng.randint(low, high)])
    if element == "boolean":
        return rng.random() < 0.5
    if element == "octet":
        return bytes([rng.randint(0, 255)])
    if element.startswith("string"):
        bound = re.match(r"string<(\d+)>", element)
        text = rng.choice(STRINGS)
        return text[:int(bound.group(1))] if bound else text
    return fill(rng, message_class(element)())


def fill(rng: random.Random, msg: object) -> object:
    """Sets every field of ``msg`` to random values, recursively; returns it."""
    for name, text in msg.get_fields_and_field_types().items():
        match = _TEXT.match(text)
        if match.group("one"):
            setattr(msg, name, scalar(rng, match.group("one")))
        elif match.group("arr"):
            element, size = match.group("arr"), int(match.group("size"))
            values = [scalar(rng, element) for _ in range(size)]
            setattr(msg, name, numpy.array(values, dtype=numpy.dtype(TYPECODES[element]))
                    if element in TYPECODES else values)
        else:
            element = match.group("seq")
            bound = int(match.group("bound") or 0)
            count = rng.choice([0, 1, 3, 17] if not bound else list(range(bound + 1)))
            values = [scalar(rng, element) for _ in range(count)]
            setattr(msg, name, array.array(TYPECODES[element], values) if element in TYPECODES else values)
    return msg
