"""Serialization under real rclpy vs rosgrade: ``real TYPES_JSON`` prints real bytes, ``ours TYPES_JSON REAL_OUT`` checks.

Real Fast DDS leaves padding bytes uninitialised and pads the end, so bytes are compared where ours are not padding
(ours write zeros there), real bytes may run past ours, and our decoder must read the real bytes back.
"""
from __future__ import annotations

import importlib
import json
import random
import sys

import numpy

from values import fill

SEEDS = 3


def odd_values() -> list[tuple[str, str, str, object]]:
    """(label, class, field, value): values that rosidl's C conversion treats oddly."""
    return [
        ("v_int1", "geometry_msgs/Vector3", "x", 1), ("v_int0", "geometry_msgs/Vector3", "x", 0),
        ("v_neg1", "geometry_msgs/Vector3", "x", -1), ("v_big", "geometry_msgs/Vector3", "x", 2 ** 40),
        ("v_str", "geometry_msgs/Vector3", "x", "abc"), ("v_bool", "geometry_msgs/Vector3", "x", True),
        ("v_np32", "geometry_msgs/Vector3", "x", numpy.float32(1.5)), ("v_np64", "geometry_msgs/Vector3", "x",
                                                                        numpy.float64(1.5)),
        ("v_npint", "geometry_msgs/Vector3", "x", numpy.int64(3)),
        ("i32_float", "std_msgs/Int32", "data", 1.5), ("i32_big", "std_msgs/Int32", "data", 2 ** 40),
        ("i32_str", "std_msgs/Int32", "data", "a"), ("i32_bool", "std_msgs/Int32", "data", True),
        ("i32_np", "std_msgs/Int32", "data", numpy.int64(7)), ("i8_wrap", "std_msgs/Int8", "data", 200),
        ("u8_300", "std_msgs/UInt8", "data", 300), ("u8_neg", "std_msgs/UInt8", "data", -1),
        ("u8_float", "std_msgs/UInt8", "data", 2.5), ("u8_np", "std_msgs/UInt8", "data", numpy.uint8(3)),
        ("i64_float", "std_msgs/Int64", "data", 2.5), ("u64_np", "std_msgs/UInt64", "data", numpy.uint64(3)),
        ("f32_int", "std_msgs/Float32", "data", 1), ("f32_huge", "std_msgs/Float32", "data", 1e300),
        ("f32_nhuge", "std_msgs/Float32", "data", -1e39),
        ("str_int", "std_msgs/String", "data", 5), ("str_bytes", "std_msgs/String", "data", b"ab"),
        ("str_nul", "std_msgs/String", "data", "a\0b"),
        ("bool_int", "std_msgs/Bool", "data", 1), ("bool_str", "std_msgs/Bool", "data", "x"),
        ("bool_np", "std_msgs/Bool", "data", numpy.bool_(True)),
        ("tw_none", "geometry_msgs/Twist", "linear", None),
        ("seq_ints", "std_msgs/Float64MultiArray", "data", [1, 2]),
        ("names_tuple", "sensor_msgs/JointState", "name", ("a", "b")),
    ]


def _class(short: str) -> type:
    """The class of ``pkg/Name`` (a message) or ``pkg/ns/Name`` (a service's part too)."""
    package, *namespace, name = short.split("/")
    return getattr(importlib.import_module(f"{package}.{namespace[0] if namespace else 'msg'}"), name)


def _outcome(fn) -> list:
    try:
        return ["bytes", fn().hex()]
    except BaseException as exc:  # noqa: BLE001 - the exception is the observation
        kind = next(k for k in type(exc).__mro__ if k.__module__ == "builtins").__name__
        cause = exc.__cause__ or exc.__context__
        return ["EXC", kind, type(cause).__name__ if cause else ""]


def real(types: list[str]) -> None:
    from rclpy.serialization import serialize_message  # noqa: PLC0415 - only in the real venv
    for type_name in types:
        cls = _class(type_name)
        for seed in range(SEEDS):
            msg = fill(random.Random(f"{type_name}:{seed}"), cls())
            print(json.dumps([type_name, seed, serialize_message(msg).hex()]))
    for label, cls_name, field, value in odd_values():
        def odd(cls_name=cls_name, field=field, value=value):
            msg = _class(cls_name)()
            setattr(msg, field, value)
            return serialize_message(msg)
        print(json.dumps(["odd", label, _outcome(odd)]))


def _matches(ours: bytes, theirs: bytes) -> bool:
    return len(theirs) >= len(ours) and all(a == b or a == 0 for a, b in zip(ours, theirs))


def ours(real_out: str) -> None:
    import rosgrade_rosidl as rr  # noqa: PLC0415 - only on rosgrade's node path
    results: dict[str, str] = {}
    odd = {label: (cls_name, field, value) for label, cls_name, field, value in odd_values()}
    for line in open(real_out):
        key, seed, data = json.loads(line)
        if key == "odd":
            cls_name, field, value = odd[seed]

            def run(cls_name=cls_name, field=field, value=value):
                msg = _class(cls_name)()
                setattr(msg, field, value)
                return rr.serialize(msg)
            got = _outcome(run)
            same = got == data or (got[0] == data[0] == "bytes" and _matches(bytes.fromhex(got[1]),
                                                                            bytes.fromhex(data[1])))
            results[f"odd:{seed}"] = "ok" if same else f"real {data}, ours {got}"
            continue
        cls = _class(key)
        msg = fill(random.Random(f"{key}:{seed}"), cls())
        mine, theirs = rr.serialize(msg), bytes.fromhex(data)
        if not _matches(mine, theirs):
            results[key] = f"seed {seed}: real {data}\n ours {mine.hex()}"
        elif rr.deserialize(cls, theirs) != msg:
            results[key] = f"seed {seed}: real bytes decode to {rr.deserialize(cls, theirs)!r}"
        else:
            results.setdefault(key, "ok")
    print(json.dumps(results))


if __name__ == "__main__":
    if sys.argv[1] == "real":
        real(json.loads(open(sys.argv[2]).read()))
    else:
        ours(sys.argv[2])
