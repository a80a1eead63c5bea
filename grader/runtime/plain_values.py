"""Messages as plain values and back, for a world that serves services with nested fields (Jazzy turtlesim's
parameter services: a list of Parameter in, a list of SetParametersResult out) without knowing the wire's classes."""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np


class PlainValuesError(Exception):
    """A world's response field that its message type does not have."""


def plain(value: Any) -> Any:
    """A decoded field as plain values: messages as dicts, arrays as lists, the rest as it is."""
    if hasattr(value, "__dataclass_fields__"):
        return {name: plain(getattr(value, name)) for name in value.__dataclass_fields__ if not name.startswith("__")}
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    return value


def nested(catalog: Any, type_name: str, values: Mapping[str, object]) -> dict[str, object]:
    """``values`` with each message-typed field (a dict, or a list of dicts) built as the catalog's class, so that
    ``cls(**values)`` encodes; fields left out keep their defaults. Only the ROS 2 catalog has nested fields to build
    (a catalog without a typestore gets the values as they are)."""
    store = getattr(catalog, "typestore", None)
    if store is None or not any(isinstance(v, (Mapping, list)) for v in values.values()):
        return dict(values)
    fields = dict(store.fielddefs[type_name][1])
    built: dict[str, object] = {}
    for name, value in values.items():
        if name not in fields:
            raise PlainValuesError(f"{type_name} has no field {name!r}")
        built[name] = _field(catalog, fields[name], value)
    return built


def _field(catalog: Any, kind: tuple, value: object) -> object:
    node, detail = kind
    if node.name == "NAME" and isinstance(value, Mapping):
        return _message(catalog, detail, value)
    if node.name in ("SEQUENCE", "ARRAY") and isinstance(value, list) and detail[0][0].name == "NAME":
        return [_message(catalog, detail[0][1], item) if isinstance(item, Mapping) else item for item in value]
    return value


def _message(catalog: Any, type_name: str, values: Mapping[str, object]) -> object:
    """One message of ``type_name`` from plain values, its unnamed fields at their defaults."""
    fields = catalog.typestore.fielddefs[type_name][1]
    given = nested(catalog, type_name, values)
    return catalog.message_class(type_name)(**{name: given[name] if name in given else _zero(catalog, kind)
                                               for name, kind in fields})


def _zero(catalog: Any, kind: tuple) -> object:
    """A field's default: zero, false, empty; a fixed array of them at its length."""
    node, detail = kind
    if node.name == "NAME":
        return _message(catalog, detail, {})
    if node.name in ("SEQUENCE", "ARRAY"):
        inner, count = detail
        length = count if node.name == "ARRAY" else 0
        if inner[0].name == "BASE" and inner[1][0] != "string":
            return np.zeros(length, dtype=_DTYPES.get(inner[1][0], "uint8"))
        return [_zero(catalog, inner) for _ in range(length)]
    base = detail[0]
    return "" if base == "string" else False if base == "bool" else 0.0 if base.startswith("float") else 0


_DTYPES = {"bool": bool, "float32": "float32", "float64": "float64", "int8": "int8", "uint8": "uint8",
           "int16": "int16", "uint16": "uint16", "int32": "int32", "uint32": "uint32", "int64": "int64",
           "uint64": "uint64", "byte": "uint8", "char": "uint8", "octet": "uint8"}
