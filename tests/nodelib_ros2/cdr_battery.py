"""Checks rosgrade_rosidl's CDR codec against rosbags for every covered type; run with the ros2 node path first.

Prints one JSON object: type name -> "ok" or what went wrong (bytes differ, round trip, truncation handling).
"""
from __future__ import annotations

import json
import random
import sys

import numpy

import rosgrade_rosidl as rr
from rosgrade_rosidl._defs import MESSAGES
from rosgrade_rosidl._model import SCALAR, spec

from gen_defs import typestore
from values import fill

_NUMPY = {"float64": numpy.float64, "float32": numpy.float32, "int8": numpy.int8, "uint8": numpy.uint8,
          "int16": numpy.int16, "uint16": numpy.uint16, "int32": numpy.int32, "uint32": numpy.uint32,
          "int64": numpy.int64, "uint64": numpy.uint64, "char": numpy.uint8, "byte": numpy.uint8,
          "bool": numpy.bool_}


def _element(store, base: str, value: object) -> object:
    if "/" in base:
        return to_rosbags(store, base, value)
    if base == "byte":
        return value[0]
    return value


def to_rosbags(store, type_name: str, msg: object) -> object:
    """The rosbags dataclass holding the same values as our message."""
    type_spec = spec(type_name)
    values = {}
    for field in type_spec.wire_fields:
        if not type_spec.fields:
            values[field.name] = 0
            continue
        value = getattr(msg, field.name)
        if field.kind == SCALAR:
            values[field.name] = _element(store, field.base, value)
        elif field.base in _NUMPY:
            items = [_element(store, field.base, v) for v in value]
            values[field.name] = numpy.array(items, dtype=_NUMPY[field.base])
        else:
            values[field.name] = [_element(store, field.base, v) for v in value]
    return store.types[type_name](**values)


def check(store, type_name: str, seeds: int) -> str:
    cls = rr.message_class(type_name)
    for seed in range(seeds):
        msg = fill(random.Random(f"{type_name}:{seed}"), cls()) if spec(type_name).fields else cls()
        ours = rr.serialize(msg)
        theirs = bytes(store.serialize_cdr(to_rosbags(store, type_name, msg), type_name))
        if ours != theirs:
            return f"seed {seed}: bytes differ\n ours   {ours.hex()}\n rosbags {theirs.hex()}"
        back = rr.deserialize(cls, ours)
        if back != msg or repr(back) != repr(msg):
            return f"seed {seed}: round trip gives {back!r}\n instead of {msg!r}"
        for cut in sorted(set(range(min(len(ours), 80))) | set(range(0, len(ours), 7)) | {len(ours) - 1}):
            try:
                rr.deserialize(cls, ours[:cut])
            except rr.DecodeError:
                continue
            except Exception as exc:  # noqa: BLE001 - any other exception is the failure being looked for
                return f"seed {seed}: {cut} of {len(ours)} bytes raise {type(exc).__name__}: {exc}"
            return f"seed {seed}: {cut} of {len(ours)} bytes decode without error"
        rng = random.Random(seed)
        for _ in range(20):
            junk = b"\x00\x01\x00\x00" + bytes(rng.randrange(256) for _ in range(rng.randrange(64)))
            try:
                rr.deserialize(cls, junk)
            except rr.DecodeError:
                pass
            except Exception as exc:  # noqa: BLE001
                return f"seed {seed}: garbage {junk.hex()} raises {type(exc).__name__}: {exc}"
    return "ok"


def main() -> None:
    seeds = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    store = typestore()
    results = {}
    for name in MESSAGES:
        try:
            results[name] = check(store, name, seeds)
        except Exception as exc:  # noqa: BLE001 - reported per type
            results[name] = f"{type(exc).__name__}: {exc}"
    print(json.dumps(results))


if __name__ == "__main__":
    main()
