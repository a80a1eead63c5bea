"""A message built from YAML-like values as `rostopic pub`, `ros2 topic pub` and `ros2 service call` build one: every
field not given at its zero value, nested messages and arrays from mappings and lists, each value checked against
its field's type."""
from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from rosbags.typesys.base import Nodetype

from grader.runtime.wire import Wire

_NUMERIC = {"bool": np.bool_, "byte": np.uint8, "char": np.uint8, "int8": np.int8, "uint8": np.uint8,
            "int16": np.int16, "uint16": np.uint16, "int32": np.int32, "uint32": np.uint32, "int64": np.int64,
            "uint64": np.uint64, "float32": np.float32, "float64": np.float64}


class MessageValueError(ValueError):
    """A value does not fit its message: a field the type does not have, or a value of another type."""


def build_message(wire: Wire, type_name: str, values: Mapping[str, object], where: str = "") -> object:
    """A message of ``type_name`` from a YAML-like mapping, every field not given at its zero value, as
    ``rostopic pub`` and ``ros2 topic pub`` fill one; MessageValueError names the field that does not fit."""
    store = wire.catalog.typestore
    name = type_name if type_name in store.fielddefs else wire.catalog.message_class(type_name).__msgtype__
    if not isinstance(values, Mapping):
        raise MessageValueError(f"{where or type_name}: expected a mapping of fields, got {values!r}")
    fields = dict(store.fielddefs[name][1])
    unknown = sorted(set(values) - set(fields))
    if unknown:
        raise MessageValueError(f"{where or type_name}: {name} has no field {unknown[0]!r}; its fields are "
                               f"{', '.join(fields) or 'none'}")
    built = {field: _field(wire, desc, values.get(field), f"{where}.{field}" if where else field)
             for field, desc in fields.items()}
    return store.types[name](**built)


def _field(wire: Wire, desc: tuple, value: object, where: str) -> object:
    node, detail = desc
    if node == Nodetype.NAME:
        return build_message(wire, detail, {} if value is None else value, where)
    if node == Nodetype.BASE:
        return _base(detail[0], value, where)
    (inner, inner_detail), count = detail
    items = list(value) if isinstance(value, (list, tuple)) else [] if value is None else None
    if items is None:
        raise MessageValueError(f"{where}: expected a list, got {value!r}")
    if node == Nodetype.ARRAY and value is not None and len(items) != count:
        raise MessageValueError(f"{where}: expected {count} items, got {len(items)}")
    if node == Nodetype.ARRAY and value is None:
        items = [None] * count
    if inner == Nodetype.NAME:
        return [build_message(wire, inner_detail, {} if item is None else item, f"{where}[{i}]")
                for i, item in enumerate(items)]
    base = inner_detail[0]
    converted = [_base(base, item, f"{where}[{i}]") for i, item in enumerate(items)]
    return np.array(converted, dtype=_NUMERIC[base]) if base in _NUMERIC else converted


def _base(base: str, value: object, where: str) -> object:
    """One field of a built-in type, as YAML gives it: ints for integers, numbers for floats, text for strings."""
    if base in ("string", "wstring"):
        if value is None:
            return ""
        if not isinstance(value, str):
            raise MessageValueError(f"{where}: expected a string, got {value!r}")
        return value
    if base == "bool":
        if value is None:
            return False
        if not isinstance(value, bool):
            raise MessageValueError(f"{where}: expected true or false, got {value!r}")
        return value
    if base in ("float32", "float64"):
        if value is None:
            return 0.0
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise MessageValueError(f"{where}: expected a number, got {value!r}")
        return float(value)
    if base in _NUMERIC:
        if value is None:
            return 0
        if isinstance(value, bool) or not isinstance(value, int):
            raise MessageValueError(f"{where}: expected an integer, got {value!r}")
        info = np.iinfo(_NUMERIC[base])
        if not info.min <= value <= info.max:
            raise MessageValueError(f"{where}: {value} does not fit a {base}")
        return value
    raise MessageValueError(f"{where}: a {base} field cannot be given in a scenario")
