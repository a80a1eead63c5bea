"""CDR (XCDR1, little-endian) encoder and decoder per message type, generated as Python source once per type.

Generated straight-line code keeps publish and delivery cheap in the lockstep loop; the layout follows rosbags'
``serialize_cdr``: alignment to the element size (at most 8) relative to the byte after the 4-byte encapsulation
header, strings as uint32 length (with NUL) + bytes + NUL, sequences as a uint32 count + elements.
"""
from __future__ import annotations

import array
import struct
import sys
from typing import Any, Callable

from . import _convert
from ._model import ARRAY, NUMERIC_CONTAINERS, SCALAR, Field, spec

HEADER = b"\x00\x01\x00\x00"
_LITTLE = sys.byteorder == "little"

# .msg primitive -> (size and alignment, struct code)
_PRIMITIVES = {
    "bool": (1, "B"), "byte": (1, "B"), "char": (1, "B"), "int8": (1, "b"), "uint8": (1, "B"),
    "int16": (2, "h"), "uint16": (2, "H"), "int32": (4, "i"), "uint32": (4, "I"), "int64": (8, "q"),
    "uint64": (8, "Q"), "float32": (4, "f"), "float64": (8, "d"),
}
_INT_BITS = {"int8": 8, "uint8": 8, "char": 8, "int16": 16, "uint16": 16, "int32": 32, "uint32": 32,
             "int64": 64, "uint64": 64}


class DecodeError(ValueError):
    """Bytes that are not one well-formed CDR message of the expected type."""


_PAD = tuple(bytes(n) for n in range(8))
_U32 = struct.Struct("<I")


def _numpy() -> Any:
    import numpy  # noqa: PLC0415 - numpy costs ~60 ms; only types with fixed numeric arrays need it
    return numpy


def _value_expr(field: Field, var: str) -> str:
    """Python expression converting the value in ``var`` as rosidl's C conversion does, fast when well typed."""
    base = field.base
    if base == "float64":
        return f"({var} if {var}.__class__ is float else AS_DOUBLE({var}))"
    if base == "float32":
        return f"AS_FLOAT32({var})"
    if base == "bool":
        return f"(1 if {var} is True else 0)"
    if base == "byte":
        return f"AS_OCTET({var})"
    bits = _INT_BITS[base]
    signed = base.startswith("int")
    low, high = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)
    uses_index = signed  # PyLong_AsLong/AsLongLong accept __index__; the unsigned variants want an int
    return (f"({var} if {var}.__class__ is int and {low} <= {var} <= {high} "
            f"else AS_INTEGER({var}, {bits}, {signed}, {uses_index}))")


class _Builder:
    """Writes the encoder and decoder source of one type and of every type it contains."""

    def __init__(self, namespace: dict) -> None:
        self.ns = namespace
        self.lines: list[str] = []
        self.tmp = 0

    def var(self) -> str:
        self.tmp += 1
        return f"v{self.tmp}"

    def struct(self, fmt: str) -> str:
        name = "S_" + fmt
        if name not in self.ns:
            self.ns[name] = struct.Struct("<" + fmt)
        return name

    # --- encoding ---------------------------------------------------------------------------------------------
    def encode(self, type_name: str, fn: str) -> list[str]:
        type_spec = spec(type_name)
        self.lines = [f"def {fn}(m, b):"]
        fields = type_spec.wire_fields
        if not type_spec.fields:  # rosidl's placeholder member of an empty struct is one zero byte
            self.lines.append("    b.append(0)")
            return self.lines
        index = 0
        while index < len(fields):
            field = fields[index]
            if field.kind == SCALAR and field.base in _PRIMITIVES:
                size = _PRIMITIVES[field.base][0]
                run = [field]
                while (index + len(run) < len(fields) and fields[index + len(run)].kind == SCALAR
                       and _PRIMITIVES.get(fields[index + len(run)].base, (0,))[0] == size):
                    run.append(fields[index + len(run)])
                self._encode_run(run, size)
                index += len(run)
                continue
            self._encode_field(field)
            index += 1
        return self.lines

    def _pad(self, indent: str, size: int) -> None:
        if size > 1:
            self.lines.append(f"{indent}b += PAD[-len(b) & {size - 1}]")

    def _encode_run(self, run: list[Field], size: int) -> None:
        fmt = "".join(_PRIMITIVES[f.base][1] for f in run)
        self._pad("    ", size)
        names = []
        for field in run:
            var = self.var()
            self.lines.append(f"    {var} = m.{field.name}")
            names.append(_value_expr(field, var))
        self.lines.append(f"    b += {self.struct(fmt)}.pack({', '.join(names)})")

    def _encode_string(self, indent: str, expr: str) -> None:
        var = self.var()
        self.lines.append(f"{indent}{var} = AS_UTF8({expr})")
        self._pad(indent, 4)
        self.lines.append(f"{indent}b += U32.pack(len({var}) + 1)")
        self.lines.append(f"{indent}b += {var}")
        self.lines.append(f"{indent}b.append(0)")

    def _encode_field(self, field: Field) -> None:
        lines = self.lines
        expr = f"m.{field.name}"
        if field.kind == SCALAR:
            if field.base in ("string", "wstring"):
                self._encode_string("    ", expr)
            else:
                lines.append(f"    {self.encoder_name(field.base)}({expr}, b)")
            return
        items = self.var()
        if not field.nested and field.idl in NUMERIC_CONTAINERS:
            size = _PRIMITIVES[field.base][0]
            dtype, typecode = NUMERIC_CONTAINERS[field.idl]
            if field.kind == ARRAY:
                lines.append(f"    {items} = NUMERIC_ARRAY({expr}, {dtype!r}, {field.size}, {field.name!r})")
            else:
                lines.append(f"    {items} = NUMERIC_SEQUENCE({expr}, {typecode!r})")
                self._pad("    ", 4)
                lines.append(f"    b += U32.pack(len({items}) // {size})")
            lines.append(f"    if {items}:")
            self._pad("        ", size)
            lines.append(f"        b += {items}")
            return
        if field.kind == ARRAY:
            lines.append(f"    {items} = FIXED({expr}, {field.size}, {field.name!r})")
        else:
            lines.append(f"    {items} = {expr}")
            self._pad("    ", 4)
            lines.append(f"    b += U32.pack(len({items}))")
        item = self.var()
        if field.base in ("bool", "byte"):
            convert = "AS_BOOL" if field.base == "bool" else "AS_OCTET"
            if field.base == "byte":
                lines.append(f"    if isinstance({items}, (bytes, bytearray)):")
                lines.append(f"        b += {items}")
                lines.append("    else:")
                lines.append(f"        b += bytes([{convert}({item}) for {item} in {items}])")
            else:
                lines.append(f"    b += bytes([{convert}({item}) for {item} in {items}])")
            return
        lines.append(f"    for {item} in {items}:")
        if field.base in ("string", "wstring"):
            self._encode_string("        ", item)
        else:
            lines.append(f"        {self.encoder_name(field.base)}({item}, b)")

    def encoder_name(self, type_name: str) -> str:
        fn = "E_" + type_name.replace("/", "_")
        if fn not in self.ns:
            self.ns[fn] = None  # reserve against recursion, then define
            sub = _Builder(self.ns)
            exec("\n".join(sub.encode(type_name, fn)), self.ns)  # noqa: S102 - source built here from the table
        return fn

    # --- decoding ---------------------------------------------------------------------------------------------
    def decode(self, type_name: str, fn: str) -> list[str]:
        type_spec = spec(type_name)
        cls_name = "C_" + type_name.replace("/", "_")
        self.ns[cls_name] = message_class(type_name)
        lines = self.lines = [f"def {fn}(d, o):", f"    m = NEW({cls_name})", "    m._check_fields = CHECK"]
        if not type_spec.fields:
            lines.append("    S_B.unpack_from(d, o)")
            lines.append("    return m, o + 1")
            self.struct("B")
            return lines
        for field in type_spec.wire_fields:
            self._decode_field(field)
        lines.append("    return m, o")
        return lines

    def _decode_string(self, indent: str, target: str) -> None:
        self._align(indent, 4)
        self.lines.append(f"{indent}{target}, o = STRING(d, o)")

    def _align(self, indent: str, size: int) -> None:
        if size > 1:
            self.lines.append(f"{indent}o += -o & {size - 1}")

    def _decode_field(self, field: Field) -> None:
        lines = self.lines
        slot = f"m._{field.name}"
        if field.kind == SCALAR:
            if field.base in _PRIMITIVES:
                size, code = _PRIMITIVES[field.base]
                self._align("    ", size)
                lines.append(f"    ({slot},) = {self.struct(code)}.unpack_from(d, o)")
                if field.base == "bool":
                    lines.append(f"    {slot} = {slot} != 0")
                elif field.base == "byte":
                    lines.append(f"    {slot} = bytes(({slot},))")
                lines.append(f"    o += {size}")
            elif field.base in ("string", "wstring"):
                self._decode_string("    ", slot)
            else:
                lines.append(f"    {slot}, o = {self.decoder_name(field.base)}(d, o)")
            return
        count = self.var()
        if field.kind == ARRAY:
            lines.append(f"    {count} = {field.size}")
        else:
            self._align("    ", 4)
            lines.append(f"    ({count},) = U32.unpack_from(d, o)")
            lines.append("    o += 4")
        if not field.nested and field.idl in NUMERIC_CONTAINERS:
            size, _ = _PRIMITIVES[field.base]
            dtype, typecode = NUMERIC_CONTAINERS[field.idl]
            if size > 1:
                lines.append(f"    if {count}:")
                self._align("        ", size)
            lines.append(f"    CHECK_ROOM(d, o, {count} * {size})")
            if field.kind == ARRAY:
                lines.append(f"    {slot} = FROM_NUMPY(d, o, {dtype!r}, {count})")
            else:
                lines.append(f"    {slot} = FROM_ARRAY(d, o, {typecode!r}, {count} * {size})")
            lines.append(f"    o += {count} * {size}")
            return
        items = self.var()
        if field.base in ("bool", "byte"):
            lines.append(f"    CHECK_ROOM(d, o, {count})")
            if field.base == "bool":
                lines.append(f"    {items} = [x != 0 for x in d[o:o + {count}]]")
            else:
                lines.append(f"    {items} = [bytes((x,)) for x in d[o:o + {count}]]")
            lines.append(f"    o += {count}")
            lines.append(f"    {slot} = {items}")
            return
        lines.append(f"    CHECK_ROOM(d, o, {count})")  # every element takes at least one byte
        lines.append(f"    {items} = []")
        item = self.var()
        lines.append(f"    for _ in range({count}):")
        if field.base in ("string", "wstring"):
            self._decode_string("        ", item)
        else:
            lines.append(f"        {item}, o = {self.decoder_name(field.base)}(d, o)")
        lines.append(f"        {items}.append({item})")
        lines.append(f"    {slot} = {items}")

    def decoder_name(self, type_name: str) -> str:
        fn = "D_" + type_name.replace("/", "_")
        if fn not in self.ns:
            self.ns[fn] = None
            sub = _Builder(self.ns)
            exec("\n".join(sub.decode(type_name, fn)), self.ns)  # noqa: S102 - source built here from the table
        return fn


def _numeric_array(value: Any, dtype: str, size: int, name: str) -> bytes:
    numpy = _numpy()
    data = numpy.asarray(value, dtype=dtype)
    if data.shape != (size,):
        raise ValueError(f"The '{name}' field holds {data.size} values, its type needs {size}")
    return data.astype("<" + data.dtype.str[1:], copy=False).tobytes()


def _numeric_sequence(value: Any, typecode: str) -> bytes:
    if value.__class__ is not array.array or value.typecode != typecode:
        value = array.array(typecode, value)
    if not _LITTLE:
        value = array.array(typecode, value)
        value.byteswap()
    return value.tobytes()


def _fixed(value: Any, size: int, name: str) -> Any:
    if len(value) != size:
        raise ValueError(f"The '{name}' field holds {len(value)} values, its type needs {size}")
    return value


def _check_room(data: Any, offset: int, needed: int) -> None:
    if needed > len(data) - offset:
        raise DecodeError(f"a sequence of {needed} bytes does not fit in the {len(data) - offset} bytes left")


def _string(data: Any, offset: int) -> tuple[str, int]:
    (length,) = _U32.unpack_from(data, offset)
    offset += 4
    end = offset + length
    if end > len(data):
        raise DecodeError(f"a string of {length} bytes does not fit in the {len(data) - offset} bytes left")
    raw = bytes(data[offset:end])
    if raw.endswith(b"\0"):
        raw = raw[:-1]
    return raw.decode("utf-8", "replace"), end


def _from_numpy(data: Any, offset: int, dtype: str, count: int) -> Any:
    numpy = _numpy()
    return numpy.frombuffer(data, dtype="<" + numpy.dtype(dtype).str[1:], count=count, offset=offset).astype(dtype)


def _from_array(data: Any, offset: int, typecode: str, nbytes: int) -> array.array:
    values = array.array(typecode)
    values.frombytes(data[offset:offset + nbytes])
    if not _LITTLE:
        values.byteswap()
    return values


def _namespace() -> dict:
    from ._classes import CHECK_FIELDS  # noqa: PLC0415 - _classes imports this module
    return {
        "PAD": _PAD, "U32": _U32, "NEW": object.__new__, "CHECK": CHECK_FIELDS,
        "AS_DOUBLE": _convert.as_double, "AS_FLOAT32": _convert.as_float32, "AS_INTEGER": _convert.as_integer,
        "AS_BOOL": _convert.as_bool, "AS_OCTET": _convert.as_octet, "AS_UTF8": _convert.as_utf8,
        "NUMERIC_ARRAY": _numeric_array, "NUMERIC_SEQUENCE": _numeric_sequence, "FIXED": _fixed,
        "CHECK_ROOM": _check_room, "STRING": _string, "FROM_NUMPY": _from_numpy, "FROM_ARRAY": _from_array,
    }


_NAMESPACE: dict = {}


def encoder(type_name: str) -> Callable[[Any, bytearray], None]:
    """``encode(msg, buffer)`` appending the message's CDR body to ``buffer``."""
    if not _NAMESPACE:
        _NAMESPACE.update(_namespace())
    return _NAMESPACE[_Builder(_NAMESPACE).encoder_name(type_name)]


def decoder(type_name: str) -> Callable[[Any, int], tuple[Any, int]]:
    """``decode(data, offset) -> (msg, end)`` reading one message body."""
    if not _NAMESPACE:
        _NAMESPACE.update(_namespace())
    return _NAMESPACE[_Builder(_NAMESPACE).decoder_name(type_name)]


def message_class(type_name: str) -> type:
    from ._classes import message_class as build  # noqa: PLC0415 - _classes imports this module
    return build(type_name)
