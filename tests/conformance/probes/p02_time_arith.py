#!/usr/bin/env python3
"""Probe 2: rospy.Time / rospy.Duration arithmetic, fields, str/repr and error texts (no init_node needed)."""
import genpy
import rospy
from rospy import Duration, Time

EXPRESSIONS = [
    "Time(5, 2500)", "repr(Time(5, 2500))", "str(Time(5, 2500))", "'%s' % Time(1, 500000000)",
    "(Time(1.5).secs, Time(1.5).nsecs)", "(Time(0, 1500000000).secs, Time(0, 1500000000).nsecs)",
    "Time(-1)", "Time(1, -5)", "Time('1')",
    "(Time.from_sec(12.345678901).secs, Time.from_sec(12.345678901).nsecs)",
    "Time.from_sec(1700000000.123456789).nsecs",
    "Time(1, 500000000).to_sec()", "Time(1, 500000000).to_time()", "Time(1, 500000000).to_nsec()",
    "Time(10) + Duration(1.5)", "Duration(1.5) + Time(10)", "Time(10) - Time(8, 5)", "type(Time(10) - Time(8, 5))",
    "Time(10) - Duration(1)", "type(Time(10) - Duration(1))", "type(Time(10) + Duration(1))",
    "Time(1) + Time(1)", "Time(1) + 1.0", "Time(1) - 1.0", "Duration(1) + 1.0", "Duration(1) - 1",
    "Duration(1) > 0.5", "Time(1) < 2", "Duration(1) == 1", "Time(1) == 1",
    "Duration(1) * 3", "Duration(1) * 1.5", "3 * Duration(1)", "type(Duration(1) * 3)",
    "Duration(3) / 2", "Duration(3) / 2.0", "Duration(3) // 2", "Duration(3) / Duration(2)",
    "Duration(3) // Duration(2)", "Duration(3) % Duration(2)", "Duration(1) / 0",
    "-Duration(3)", "abs(Duration(-3))", "type(-Duration(3))",
    "(Duration(-0.5).secs, Duration(-0.5).nsecs)", "(Duration.from_sec(-1.25).secs, Duration.from_sec(-1.25).nsecs)",
    "str(Duration(-0.5))", "repr(Duration(2, 5))", "Duration(2, 5).to_sec()", "Duration(1.5).to_nsec()",
    "bool(Time(0))", "bool(Duration(0))", "bool(Time(0, 1))", "Time(0).is_zero()", "Duration(0).is_zero()",
    "float(Time(1, 5))", "int(Time(1, 5))", "float(Duration(1, 5))",
    "Time(1) == Duration(1)", "genpy.Time(3) == Time(3)", "Time(3) == genpy.Time(3)", "hash(Time(3)) == hash(Time(3))",
    "Duration(2) == genpy.Duration(2)", "Time(1, 5) < Time(1, 6)", "Duration(-1) < Duration(0)",
    "max(Time(1), Time(2))", "sorted([Duration(3), Duration(1)])", "Time(2) - Time(3)",
    "rospy.Time.__mro__", "rospy.Duration.__mro__",
    "Time(1).secs", "Time(1).nsecs", "Time(1, 5).__slots__ if hasattr(Time(1, 5), '__slots__') else None",
    "Time(secs=2, nsecs=3)", "Duration(secs=2, nsecs=3)", "Time(2**31)",
    "Time(1, 2).__getstate__()",
    "str(rospy.Time(1,500000000).to_sec())", "'%.3f' % Time(2, 500000000).to_sec()",
    "Duration(0.1) * 10 == Duration(1)", "round(Duration(0.3).to_sec(), 9)",
]


def show(value):
    if isinstance(value, type):
        return "<class %s.%s>" % (value.__module__, value.__name__)
    if isinstance(value, tuple) and value and all(isinstance(v, type) for v in value):
        return "(" + ", ".join("%s.%s" % (v.__module__, v.__name__) for v in value) + ")"
    return "%r (%s)" % (value, type(value).__name__)


for expr in EXPRESSIONS:
    try:
        print(expr, "->", show(eval(expr)))
    except Exception as e:
        print(expr, "!!", "%s.%s: %s" % (type(e).__module__, type(e).__name__, e))
