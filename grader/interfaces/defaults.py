"""Field default values of a ROS 2 .msg section (``int32 retries 3``), which rosbags' parser accepts but drops.

rosbags gives the fields in order; this reads only the third word of each field line, as rosidl_adapter does, and
converts it to the field's Python value (what rosidl_generator_py's ``FIELD__DEFAULT`` returns).
"""
from __future__ import annotations

import ast
import re

from rosbags.typesys.base import Nodetype

_LINE = re.compile(r"^([^\s#]+)\s+([^\s=#]+)\s*(.*)$")  # type, name, what follows (a default, or =value)
_INTS = frozenset({"byte", "char", "int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64"})


class DefaultError(ValueError):
    """A default value that does not fit its field's type."""


def _scalar(base: str, text: str) -> object:
    if base == "bool":
        lowered = text.lower()
        if lowered in ("true", "1"):
            return True
        if lowered in ("false", "0"):
            return False
        raise DefaultError(f"{text!r} is not a bool")
    if base in _INTS:
        return int(text, 0)
    if base in ("float32", "float64"):
        return float(text)
    if base in ("string", "wstring"):
        if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":
            return ast.literal_eval(text)
        return text
    raise DefaultError(f"no default for a {base} field")


def _value(desc: tuple, text: str) -> object:
    node, detail = desc
    if node in (Nodetype.ARRAY, Nodetype.SEQUENCE):
        (node, detail), _ = detail
        if node != Nodetype.BASE or not (text.startswith("[") and text.endswith("]")):
            raise DefaultError(f"{text!r} is not a list")
        inner = text[1:-1].strip()
        return [_scalar(detail[0], part.strip()) for part in inner.split(",")] if inner else []
    if node != Nodetype.BASE:
        raise DefaultError("a nested message has no default")
    return _scalar(detail[0], text)


def _default_text(rest: str) -> str:
    """The default's text from what follows the field name, without a trailing comment."""
    rest = rest.strip()
    if rest and rest[0] in "'\"":
        end = rest.find(rest[0], 1)
        while end > 0 and rest[end - 1] == "\\":
            end = rest.find(rest[0], end + 1)
        return rest[:end + 1] if end > 0 else rest
    return rest.split("#", 1)[0].strip()


def field_defaults(section: str, typedef: tuple[list, list]) -> dict[str, object]:
    """``{field: default}`` for the fields of ``typedef`` (parsed from ``section``) that give one; a default that
    does not convert is left out (rosidl would refuse the file; the field then takes its type's zero)."""
    fields = iter(typedef[1])
    found: dict[str, object] = {}
    for line in section.splitlines():
        match = _LINE.match(line.strip())
        if match is None or match.group(3).startswith("="):
            continue  # blank, a comment or a constant
        fname, desc = next(fields, (None, None))
        if fname is None:
            break
        text = _default_text(match.group(3))
        if text:
            try:
                found[fname] = _value(desc, text)
            except (ValueError, SyntaxError):
                continue
    return found
