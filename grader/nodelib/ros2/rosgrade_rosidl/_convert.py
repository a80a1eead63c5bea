"""How rosidl's C conversion turns a field's Python value into the wire value, including its odd cases.

The real C code (rosidl_generator_py's _msg_support.c) only asserts field types in debug builds, so release ROS 2
serializes whatever a field holds: an int in a float64 field is read as a float object (the int's internal size word
becomes the double's bits, about 5e-324 for 1), a bool field is 1 only for ``True``, integers are truncated to the
field's width, and values that Python's C API refuses raise. Students hit these (``msg.angular.z = 1`` barely turns
the robot), so rosgrade reproduces them instead of coercing.
"""
from __future__ import annotations

import operator
import struct
import sys

_DOUBLE_FROM_INT64 = struct.Struct("<q")
_DOUBLE = struct.Struct("<d")
_PY312 = sys.version_info >= (3, 12)
# float32 conversion rounds to nearest: from this magnitude up a double becomes +-inf.
_FLOAT32_OVERFLOW = 2.0 ** 128 - 2.0 ** 103


class FieldConversionError(SystemError):
    """A field value that rosidl's C conversion rejects (rclpy surfaces it as this SystemError)."""


def _size_word(value: object) -> int:
    """The machine word a CPython object holds right after its header, where a float keeps its value."""
    if isinstance(value, int):  # bool included
        number = int(value)
        digits = (abs(number).bit_length() + 29) // 30
        if _PY312:  # lv_tag: digit count << 3 | sign (0 positive, 1 zero, 2 negative)
            return (digits << 3) | (1 if number == 0 else 2 if number < 0 else 0)
        return -digits if number < 0 else digits
    if isinstance(value, (str, bytes, bytearray, list, tuple, dict)):
        return len(value)
    raw = getattr(value, "tobytes", None)
    if raw is not None and type(value).__module__ == "numpy":  # a numpy scalar: its value follows the header
        data = (raw() + bytes(8))[:8]
        return _DOUBLE_FROM_INT64.unpack(data)[0]
    return 0


def as_double(value: object) -> float:
    """What ``PyFloat_AS_DOUBLE(value)`` yields: the float itself, else the object's size word read as a double."""
    if isinstance(value, float):
        return float(value)
    return _DOUBLE.unpack(_DOUBLE_FROM_INT64.pack(_size_word(value)))[0]


def as_float32(value: object) -> float:
    """A double narrowed as C narrows it: out-of-range magnitudes become infinities instead of raising."""
    number = value if value.__class__ is float else as_double(value)
    if -_FLOAT32_OVERFLOW < number < _FLOAT32_OVERFLOW or number != number:
        return number
    return float("inf") if number > 0 else float("-inf")


def as_integer(value: object, bits: int, signed: bool, uses_index: bool) -> int:
    """``(intN_t)PyLong_AsLong(value)`` and friends: C long conversion, then truncation to the field's width."""
    try:
        if isinstance(value, int):
            number = int(value)
        elif uses_index:
            number = operator.index(value)
        else:
            raise TypeError("an integer is required")
        if uses_index and not -(1 << 63) <= number < (1 << 63):
            raise OverflowError("Python int too large to convert to C long")
        if not uses_index:
            if number < 0:
                raise OverflowError("can't convert negative int to unsigned")
            if number >= 1 << 64:
                raise OverflowError("Python int too large to convert to C unsigned long")
    except (TypeError, OverflowError) as exc:
        raise FieldConversionError("<built-in method serialize> returned a result with an exception set") from exc
    number &= (1 << bits) - 1
    if signed and number >= 1 << (bits - 1):
        number -= 1 << bits
    return number


def as_bool(value: object) -> int:
    """rosidl stores ``value == Py_True``: only the object True is true."""
    return 1 if value is True else 0


def as_octet(value: object) -> int:
    """First byte of a bytes value (the terminating NUL for b'')."""
    if isinstance(value, (bytes, bytearray)):
        return value[0] if value else 0
    raise TypeError(f"an octet field must hold bytes, not {type(value).__name__}")


def as_utf8(value: object) -> bytes:
    """UTF-8 of a str, cut at its first NUL as rosidl's C string copy cuts it."""
    if not isinstance(value, str):
        raise TypeError("bad argument type for built-in operation")
    data = value.encode()
    cut = data.find(b"\0")
    return data if cut < 0 else data[:cut]
