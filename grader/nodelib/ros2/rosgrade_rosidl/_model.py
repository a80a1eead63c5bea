"""The field model of one message type, read from the generated definition table, shared by classes and the codec."""
from __future__ import annotations

import json
import re
from functools import lru_cache
from typing import NamedTuple

from . import _defs

SCALAR, ARRAY, SEQUENCE = 0, 1, 2
EMPTY_MEMBER = "structure_needs_at_least_one_member"

# .msg primitive -> IDL type name, as rosidl_adapter maps them (ROS 2 ``char`` is an unsigned byte).
IDL_NAMES = {
    "bool": "boolean", "byte": "octet", "char": "uint8", "float32": "float", "float64": "double",
    "int8": "int8", "uint8": "uint8", "int16": "int16", "uint16": "uint16", "int32": "int32", "uint32": "uint32",
    "int64": "int64", "uint64": "uint64", "string": "string", "wstring": "wstring",
}
# IDL numeric type -> (numpy dtype name, array.array type code): the types rosidl stores in numpy/array containers.
NUMERIC_CONTAINERS = {
    "float": ("float32", "f"), "double": ("float64", "d"), "int8": ("int8", "b"), "uint8": ("uint8", "B"),
    "int16": ("int16", "h"), "uint16": ("uint16", "H"), "int32": ("int32", "i"), "uint32": ("uint32", "I"),
    "int64": ("int64", "q"), "uint64": ("uint64", "Q"),
}


class UnknownType(LookupError):
    """A message or service type the definition table does not hold."""


class Field(NamedTuple):
    name: str
    base: str          # .msg primitive ('float64', 'string', ...) or a full type name ('std_msgs/msg/Header')
    kind: int          # SCALAR, ARRAY or SEQUENCE
    size: int          # array length, or sequence bound (0: unbounded)
    string_bound: int  # bound of a bounded string (0: unbounded)
    default: object    # the .msg default value, or None

    @property
    def nested(self) -> bool:
        return "/" in self.base

    @property
    def idl(self) -> str:
        """IDL type name of a primitive element ('double', 'boolean', 'string', ...)."""
        return IDL_NAMES[self.base]


class TypeSpec(NamedTuple):
    name: str                          # "geometry_msgs/msg/Twist"
    fields: tuple[Field, ...]          # the fields a Python class shows
    wire_fields: tuple[Field, ...]     # the fields on the wire (an empty struct carries one uint8)
    constants: tuple[tuple[str, str, object], ...]
    hash: str


@lru_cache(maxsize=None)
def spec(type_name: str) -> TypeSpec:
    """The TypeSpec of ``pkg/msg/Name`` (also ``pkg/srv/Name_Request`` etc.)."""
    try:
        raw_fields, constants, rihs = json.loads(_defs.MESSAGES[type_name])
    except KeyError:
        raise UnknownType(f"unknown message type {type_name!r}") from None
    wire = tuple(Field(*f) for f in raw_fields)
    shown = () if len(wire) == 1 and wire[0].name == EMPTY_MEMBER else wire
    return TypeSpec(type_name, shown, wire, tuple(tuple(c) for c in constants), rihs)


def snake_case(name: str) -> str:
    """rosidl's module name of an interface: 'TwistStamped' -> 'twist_stamped', 'TFMessage' -> 'tf_message'."""
    name = re.sub(r"(.)([A-Z][a-z]+)", r"\1_\2", name)
    return re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", name).lower()
