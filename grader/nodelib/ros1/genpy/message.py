"""genpy.Message: the base of every message class, with genpy's constructor, equality, YAML-like text and type checks."""
from __future__ import annotations

import codecs
import copy
import logging
import re
import struct
import sys

from .rostime import Duration, Time, TVal

struct_I = struct.Struct("<I")

_INT_WIDTHS = {"byte": 8, "char": 8, "int8": 8, "uint8": 8, "int16": 16, "uint16": 16,
               "int32": 32, "uint32": 32, "int64": 64, "uint64": 64}
_UNSIGNED = {"char", "uint8", "uint16", "uint32", "uint64"}


_PLAIN_FLOAT_TYPES = (float, int)
_numpy_float_types: tuple = ()


def _valid_float_types() -> tuple:
    """The exact types genpy's check accepts for float fields.

    numpy is not imported here: it would add ~0.1 s to every node's start-up, and a value can only be a numpy
    type if the node imported numpy itself, so its types are looked up once numpy is in sys.modules.
    """
    global _numpy_float_types
    np = sys.modules.get("numpy")
    if np is None:
        return _PLAIN_FLOAT_TYPES
    if not _numpy_float_types:
        _numpy_float_types = (float, int, np.float32, np.float64, np.int8, np.int16, np.int32, np.int64,
                              np.uint8, np.uint16, np.uint32, np.uint64)
    return _numpy_float_types


def _numpy1_copy(msg: Message, np) -> Message | None:
    """A copy of msg whose float fields hold plain floats where they held size-1 numpy arrays (None: no such field)."""
    changed = False

    def fixed(value, type_):
        nonlocal changed
        if type_ in ("float32", "float64") and isinstance(value, np.ndarray) and value.size == 1:
            changed = True
            return float(value.reshape(-1)[0])
        if isinstance(value, Message):
            return _fields_fixed(value)
        if type(value) in (list, tuple) and type_.endswith("]"):
            return [fixed(item, type_[:type_.index("[")]) for item in value]
        return value

    def _fields_fixed(m: Message) -> Message:
        out = copy.copy(m)
        for name, type_ in zip(m.__slots__, m._slot_types):
            setattr(out, name, fixed(getattr(m, name), type_))
        return out

    result = _fields_fixed(msg)
    return result if changed else None


def numpy1_retry(msg: Message, buff, start: int) -> bool:
    """Serialize again as genpy does on numpy 1, where struct.pack took a size-1 array as a float (numpy 2 refuses);
    False when msg holds no such value, so the original error stands."""
    np = sys.modules.get("numpy")
    if np is None:
        return False
    plain = _numpy1_copy(msg, np)
    if plain is None:
        return False
    buff.seek(start)
    buff.truncate()
    plain.serialize(buff)
    return True


class MessageException(Exception):
    """Base exception for message errors."""


class DeserializationError(MessageException):
    """Message bytes could not be decoded."""


class SerializationError(MessageException):
    """A field holds a value that cannot be written."""


class _ReplaceOnce:
    """The 'rosmsg' codec error handler: replace bad UTF-8, logging the first occurrence (as genpy does)."""

    def __init__(self) -> None:
        self.warned = False
        self.msg_type: str | None = None

    def __call__(self, err):
        if not self.warned:
            self.warned = True
            what = "message %s" % self.msg_type if self.msg_type else "unknown message"
            logging.getLogger("rosout").error(
                "Characters replaced when decoding %s (will print only once): %s", what, err)
        return codecs.replace_errors(err)


_rosmsg_errors = _ReplaceOnce()
codecs.register_error("rosmsg", _rosmsg_errors)


def is_simple(type_: str) -> bool:
    return type_ in _INT_WIDTHS or type_ in ("float32", "float64", "bool", "string", "time", "duration")


def isstring(value) -> bool:
    return isinstance(value, (str, bytes))


def check_type(field_name: str, field_type: str, field_val) -> None:
    """Raise SerializationError when field_val cannot be written as field_type (genpy's rules and texts)."""
    if field_type in ("float32", "float64"):
        if type(field_val) not in _valid_float_types():
            raise SerializationError("field %s must be float type" % field_name)
    elif field_type in _INT_WIDTHS:
        unsigned = field_type in _UNSIGNED
        if type(field_val) is not int:
            raise SerializationError("field %s must be %s" % (
                field_name, "unsigned integer type" if unsigned else "an integer type"))
        bits = _INT_WIDTHS[field_type]
        if unsigned:
            if field_val < 0:
                raise SerializationError("field %s must be unsigned integer type" % field_name)
            limit = 1 << bits
            if field_val >= limit:
                raise SerializationError("field %s exceeds specified width [%s]" % (field_name, field_type))
        elif not -(1 << (bits - 1)) <= field_val < (1 << (bits - 1)):
            raise SerializationError("field %s exceeds specified width [%s]" % (field_name, field_type))
    elif field_type == "bool":
        if field_val not in (True, False, 0, 1):
            raise SerializationError("field %s is not a bool" % field_name)
    elif field_type == "string":
        if type(field_val) is str:
            try:
                field_val.encode("ascii")
            except UnicodeEncodeError:
                raise SerializationError("field %s is a non-ascii string" % field_name) from None
        elif type(field_val) is not bytes:
            raise SerializationError("field %s must be of type bytes or an ascii string" % field_name)
    elif field_type == "time":
        if not isinstance(field_val, Time):
            raise SerializationError("field %s must be of type Time" % field_name)
    elif field_type == "duration":
        if not isinstance(field_val, Duration):
            raise SerializationError("field %s must be of type Duration" % field_name)
    elif field_type.endswith("]"):
        base = field_type[:field_type.index("[")]
        if base in ("uint8", "char") and isinstance(field_val, (str, bytes)):
            return
        if type(field_val) not in (list, tuple):
            if isinstance(field_val, str):
                raise SerializationError(
                    "field %s must be a list or tuple type. Only uint8[] can be a string" % field_name)
            raise SerializationError("field %s must be a list or tuple type" % field_name)
        for value in field_val:
            check_type(field_name + "[]", base, value)
    elif isinstance(field_val, Message):
        if field_val._type != field_type and not (field_type == "Header" and field_val._type == "std_msgs/Header"):
            raise SerializationError("field %s must be of type %s instead of %s" % (
                field_name, field_type, field_val._type))
        for name, type_ in zip(field_val.__slots__, field_val._slot_types):
            check_type("%s.%s" % (field_name, name), type_, getattr(field_val, name))
    else:
        raise SerializationError("field %s must be of type [%s]" % (field_name, field_type))


# --- str(): genpy's YAML-like text -----------------------------------------------------------------------------

_YAML_ESCAPES = {"\0": "0", "\x07": "a", "\x08": "b", "\x09": "t", "\x0a": "n", "\x0b": "v", "\x0c": "f",
                 "\x0d": "r", "\x1b": "e", '"': '"', "\\": "\\", "\x85": "N", "\xa0": "_",
                 "\u2028": "L", "\u2029": "P"}
# plain scalars that YAML would read back as something other than a string
_YAML_SPECIAL = re.compile(r"""^(?:~|null|Null|NULL|true|True|TRUE|false|False|FALSE|yes|Yes|YES|no|No|NO|on|On|ON
    |off|Off|OFF|y|Y|n|N|=|<<|[-+]?(?:[0-9][0-9_]*)?\.[0-9_]*(?:[eE][-+][0-9]+)?|[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+\.[0-9_]*
    |[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN)|[-+]?0b[0-1_]+|[-+]?0[0-7_]+|[-+]?(?:0|[1-9][0-9_]*)|[-+]?0x[0-9a-fA-F_]+
    |[-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+|[0-9]{4}-[0-9]{1,2}-[0-9]{1,2}.*)$""", re.X)


def _yaml_double_quoted(text: str) -> str:
    """text in YAML double quotes, escaped like PyYAML without allow_unicode (long-line folding is not modelled)."""
    out = []
    for ch in text:
        code = ord(ch)
        if ch in _YAML_ESCAPES:
            out.append("\\" + _YAML_ESCAPES[ch])
        elif 0x20 <= code <= 0x7E:
            out.append(ch)
        elif code <= 0xFF:
            out.append("\\x%02X" % code)
        elif code <= 0xFFFF:
            out.append("\\u%04X" % code)
        else:
            out.append("\\U%08X" % code)
    return '"' + "".join(out) + '"'


def _yaml_scalar(text: str) -> str:
    """text as PyYAML's default dumper writes a list item: plain, 'single' or "double" quoted."""
    if text == "":
        return "''"
    if any(not (0x20 <= ord(c) <= 0x7E) for c in text):
        return _yaml_double_quoted(text)
    plain = (text[0] not in "-?:,[]{}#&*!|>'\"%@`" and text[0] != " " and text[-1] != " "
             and ": " not in text and " #" not in text and not text.endswith(":")
             and not _YAML_SPECIAL.match(text))
    if text[0] in "-?:" and len(text) > 1 and text[1] != " ":
        plain = plain or (": " not in text and " #" not in text and not _YAML_SPECIAL.match(text))
    return text if plain else "'" + text.replace("'", "''") + "'"


def _inline_item(value) -> str:
    """One element of an inline number list; numpy scalars print as numpy 1.x did (no type wrapper)."""
    return str(value) if type(value).__module__ == "numpy" else repr(value)


def strify_message(val, indent: str = "", time_offset=None, current_time=None, field_filter=None,
                   fixed_numeric_width=None) -> str:
    """genpy's text for a message or field value (what str()/repr() of a message return)."""
    if isinstance(val, Message):
        lines = []
        for name, type_ in zip(val.__slots__, val._slot_types):
            field = getattr(val, name)
            if type(field) is bytes and type_.startswith(("uint8[", "char[")):
                field = list(field)  # byte arrays print as numbers
            text = strify_message(field, indent + "  ")
            sep = ": \n" if isinstance(field, (Message, TVal)) or _is_block_list(field) else ": "
            lines.append("%s%s%s%s" % (indent, name, sep, text))
        return "\n".join(lines)
    if isinstance(val, TVal):
        return "%ssecs: %s\n%snsecs: %9d" % (indent, val.secs, indent, val.nsecs)
    if type(val) in (list, tuple):
        if not val:
            return "[]"
        if type(val[0]) in (int, float, bool):
            return "[" + ", ".join(_inline_item(v) for v in val) + "]"
        if type(val[0]) is str:
            items = [_yaml_scalar(v) if type(v) is str else ("null" if v is None else str(v)) for v in val]
        else:
            items = ["\n" + strify_message(v, indent + "  ") if isinstance(v, (Message, TVal))
                     else strify_message(v, indent + "  ") for v in val]
        return "\n".join("%s- %s" % (indent, item) for item in items)
    if isinstance(val, str):
        return _yaml_double_quoted(val) if val else "''"
    return str(val)


def _is_block_list(value) -> bool:
    return type(value) in (list, tuple) and bool(value) and type(value[0]) not in (int, float, bool)


class Message:
    """Base class of generated message classes: slots only, positional-or-keyword constructor, value equality."""

    __slots__ = ["_connection_header"]
    _type = ""
    _md5sum = ""
    _full_text = ""
    _has_header = False
    _slot_types: list = []

    def __init__(self, *args, **kwds):
        if args and kwds:
            raise TypeError("Message constructor may only use args OR keywords, not both")
        slots = self.__slots__
        if args:
            if len(args) != len(slots):
                raise TypeError("Invalid number of arguments, args should be %s" % str(slots) + " args are" + str(args))
            for name, value in zip(slots, args):
                setattr(self, name, value)
        else:
            for key in kwds:
                if key not in slots:
                    raise AttributeError("%s is not an attribute of %s" % (key, self.__class__.__name__))
            for name in slots:
                setattr(self, name, kwds.get(name))

    def __getstate__(self):
        return [getattr(self, name) for name in self.__slots__]

    def __setstate__(self, state):
        for name, value in zip(self.__slots__, state):
            setattr(self, name, value)

    def _get_types(self):
        return self._slot_types

    def _check_types(self, exc=None):
        """Find the field that broke serialization and name it; otherwise re-raise exc."""
        for name, type_ in zip(self.__slots__, self._slot_types):
            check_type(name, type_, getattr(self, name))
        if exc:
            raise exc

    def __repr__(self):
        return strify_message(self)

    __str__ = __repr__

    def __eq__(self, other):
        if not isinstance(other, self.__class__):
            return False
        return all(getattr(self, name) == getattr(other, name) for name in self.__slots__)

    def __ne__(self, other):
        return not self.__eq__(other)

    __hash__ = None

    def serialize(self, buff):
        raise NotImplementedError

    def deserialize(self, str):  # noqa: A002 - genpy's parameter name
        raise NotImplementedError
