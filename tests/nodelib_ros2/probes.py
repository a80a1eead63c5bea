"""Behaviour probes of ROS 2 message classes, run under real rosidl (the ROS 2 venv) and under rosgrade's runtime.

Usage: python probes.py TYPES_JSON; prints one JSON line per probe: [probe id, rendered result]. Stdlib + numpy only.
"""
from __future__ import annotations

import array
import copy
import importlib
import json
import sys

import numpy

CANDIDATES = [("int", 1), ("float", 1.5), ("neg", -1), ("big", 2 ** 40), ("str", "a"), ("bool", True),
              ("none", None), ("list3", [1.0, 2.0, 3.0]), ("bytes", b"a"), ("nan", float("nan")),
              ("huge", 1e300), ("intlist", [1, 2]), ("tuple", ("x",)), ("f32arr", array.array("f", [1.0])),
              ("np36", numpy.zeros(36)), ("np9i", numpy.zeros(9, dtype=numpy.int32))]


def render(value: object) -> object:
    """A JSON-able, comparable picture of a value (type names plus contents)."""
    if isinstance(value, float):
        return ["float", repr(value)]
    if isinstance(value, (bool, int, str)) or value is None:
        return value
    if isinstance(value, bytes):
        return ["bytes", value.hex()]
    if isinstance(value, numpy.ndarray):
        return ["ndarray", str(value.dtype), list(value.shape), [render(v) for v in value.tolist()]]
    if isinstance(value, array.array):
        return ["array", value.typecode, [render(v) for v in value]]
    if isinstance(value, (list, tuple)):
        return [type(value).__name__, [render(v) for v in value]]
    if isinstance(value, dict):
        return ["dict", [[render(k), render(v)] for k, v in value.items()]]
    if hasattr(type(value), "get_fields_and_field_types"):
        return ["msg", repr(value)]
    return ["other", type(value).__name__]


def attempt(fn) -> object:
    try:
        return render(fn())
    except BaseException as exc:  # noqa: BLE001 - the exception is the observation
        return ["EXC", type(exc).__name__, str(exc)]


def slot_type(t: object) -> object:
    attrs = {name: getattr(t, name) for name in ("typename", "namespaces", "name", "maximum_size", "size")
             if hasattr(t, name)}
    if hasattr(t, "value_type"):
        attrs["value_type"] = slot_type(t.value_type)
    return [type(t).__name__, {k: render(v) if k != "value_type" else v for k, v in attrs.items()}]


def class_probes(cls: type) -> list[tuple[str, object]]:
    out: list[tuple[str, object]] = [
        ("repr", attempt(lambda: repr(cls()))),
        ("fields", attempt(cls.get_fields_and_field_types)),
        ("slots", list(cls.__slots__)),
        ("slot_types", [slot_type(t) for t in cls.SLOT_TYPES]),
        ("metaclass", type(cls).__name__),
        ("module", cls.__module__),
        ("doc", cls.__doc__),
        ("class_attrs", sorted(k for k in vars(cls) if not k.startswith("__"))),
        ("meta_attrs", sorted(k for k in vars(type(cls)) if not k.startswith("__") and k != "_rosgrade_type")),
        ("constants", [[k, render(getattr(cls, k))] for k in sorted(vars(cls)) if k.isupper()]),
        ("eq_default", attempt(lambda: cls() == cls())),
        ("eq_other", attempt(lambda: cls() == 5)),
        ("hashable", attempt(lambda: hash(cls()))),
        ("copy", attempt(lambda: repr(copy.copy(cls())) == repr(cls()))),
        ("deepcopy", attempt(lambda: repr(copy.deepcopy(cls())))),
        ("bad_kwarg", attempt(lambda: repr(cls(zzz=1, aaa=2)))),
        ("check_kwarg", attempt(lambda: repr(cls(check_fields=True)))),
        ("bad_kwarg_checked", attempt(lambda: repr(cls(zzz=1, check_fields=True)))),
    ]
    for field in cls.get_fields_and_field_types():
        out.append((f"default.{field}", attempt(lambda: getattr(cls(), field))))
        for label, value in CANDIDATES:
            def set_field(value=value, checked=False):
                msg = cls(check_fields=checked) if checked else cls()
                setattr(msg, field, copy.copy(value))
                return getattr(msg, field)
            out.append((f"set.{field}.{label}", attempt(set_field)))
            out.append((f"set_checked.{field}.{label}", attempt(lambda: set_field(checked=True))))
            out.append((f"init.{field}.{label}", attempt(lambda value=value: repr(cls(**{field: copy.copy(value)})))))
    return out


def extra_probes() -> list[tuple[str, object]]:
    """Targeted behaviour: the eq quirk, copies, sequences, constants, services."""
    from geometry_msgs.msg import PoseWithCovariance, Quaternion, Twist, Vector3
    from rcl_interfaces.msg import Log
    from sensor_msgs.msg import JointState, LaserScan
    from std_msgs.msg import Float64MultiArray

    def eq_one_differs():
        a, b = PoseWithCovariance(), PoseWithCovariance()
        b.covariance[3] = 1.0
        return a == b

    def eq_all_differ():
        a, b = PoseWithCovariance(), PoseWithCovariance()
        b.covariance = numpy.ones(36)
        return a == b

    def deepcopy_independent():
        t = Twist()
        u = copy.deepcopy(t)
        u.linear.x = 2.0
        return [t.linear.x, u.linear.x, t == copy.deepcopy(t)]

    def constant_set():
        Log.INFO = 3

    def ranges():
        scan = LaserScan()
        scan.ranges = [1.0, 2.5]
        return [repr(scan.ranges), repr(scan)]

    def joint_names():
        js = JointState(name=["a", "b"], position=[1.0, 2.0])
        return repr(js)

    def fma():
        return repr(Float64MultiArray(data=[1, 2, 3]))

    return [
        ("eq_one_differs", attempt(eq_one_differs)),
        ("eq_all_differ", attempt(eq_all_differ)),
        ("deepcopy_independent", attempt(deepcopy_independent)),
        ("log_constants", [Log.DEBUG, Log.INFO, Log.WARN, Log.ERROR, Log.FATAL, Log().INFO]),
        ("constant_set", attempt(constant_set)),
        ("quaternion_default", attempt(lambda: [Quaternion.W__DEFAULT, repr(Quaternion())])),
        ("ranges", attempt(ranges)),
        ("joint_names", attempt(joint_names)),
        ("fma", attempt(fma)),
        ("vector_kwargs", attempt(lambda: repr(Vector3(x=1.0, y=2, z="q")))),
        ("cov_short_init", attempt(lambda: PoseWithCovariance(covariance=[1.0] * 3))),
        ("cov_list_init", attempt(lambda: PoseWithCovariance(covariance=[1] * 36).covariance)),
        ("twist_positional", attempt(lambda: Twist(Vector3()))),
    ]


def main() -> None:
    types = json.loads(open(sys.argv[1]).read())
    for type_name in types:
        package, namespace, name = type_name.split("/")
        cls = getattr(importlib.import_module(f"{package}.{namespace}"), name)
        for probe, result in class_probes(cls):
            print(json.dumps([f"{type_name}:{probe}", result]))
    for probe, result in extra_probes():
        print(json.dumps([probe, result]))


if __name__ == "__main__":
    main()
