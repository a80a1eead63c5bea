#!/usr/bin/env python3
"""Probe 5: rclpy.time.Time / Duration values, arithmetic, comparisons and the errors they raise (no ROS graph)."""
import rclpy
import rclpy.timer
from builtin_interfaces.msg import Time as TimeMsg
from rclpy.clock import ClockType
from rclpy.duration import Duration
from rclpy.time import Time


def show(label, fn):
    try:
        value = fn()
        print(label, "->", repr(value), "(%s)" % type(value).__name__)
    except Exception as e:
        print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))


show("Time()", lambda: Time())
show("Time(seconds=1.5)", lambda: Time(seconds=1.5))
show("Time(seconds=1, nanoseconds=5)", lambda: Time(seconds=1, nanoseconds=5))
show("Time(seconds=-1)", lambda: Time(seconds=-1))
show("Time(nanoseconds=1.7)", lambda: Time(nanoseconds=1.7))
show("Time(seconds=2).seconds_nanoseconds()", lambda: Time(seconds=2.25).seconds_nanoseconds())
show("Time(seconds=2.25).to_msg()", lambda: Time(seconds=2.25).to_msg())
show("Time.from_msg(TimeMsg(sec=3, nanosec=7))", lambda: Time.from_msg(TimeMsg(sec=3, nanosec=7)))
show("Time(seconds=3) - Time(seconds=1)", lambda: Time(seconds=3) - Time(seconds=1))
show("Time(seconds=3) - Duration(seconds=1)", lambda: Time(seconds=3) - Duration(seconds=1))
show("Time(seconds=3) + Duration(seconds=1)", lambda: Time(seconds=3) + Duration(seconds=1))
show("Duration(seconds=1) + Time(seconds=3)", lambda: Duration(seconds=1) + Time(seconds=3))
show("Time(seconds=3) + Time(seconds=1)", lambda: Time(seconds=3) + Time(seconds=1))
show("Time(seconds=1) - Time(seconds=3)", lambda: Time(seconds=1) - Time(seconds=3))
show("Time(seconds=1) - Duration(seconds=3)", lambda: Time(seconds=1) - Duration(seconds=3))
show("Time(seconds=1) < Time(seconds=2)", lambda: Time(seconds=1) < Time(seconds=2))
show("Time(seconds=1) == Time(seconds=1)", lambda: Time(seconds=1) == Time(seconds=1))
show("Time(ROS_TIME) == Time(SYSTEM_TIME)",
     lambda: Time(seconds=1) == Time(seconds=1, clock_type=ClockType.SYSTEM_TIME))
show("Time(ROS_TIME) < Time(SYSTEM_TIME)",
     lambda: Time(seconds=1) < Time(seconds=2, clock_type=ClockType.SYSTEM_TIME))
show("Time(ROS_TIME) - Time(SYSTEM_TIME)",
     lambda: Time(seconds=1) - Time(seconds=2, clock_type=ClockType.SYSTEM_TIME))
show("Time(seconds=1) < 2", lambda: Time(seconds=1) < 2)
show("Time(seconds=1) == 1", lambda: Time(seconds=1) == 1)
show("Duration(seconds=-0.5)", lambda: Duration(seconds=-0.5))
show("Duration(seconds=1.5).nanoseconds", lambda: Duration(seconds=1.5).nanoseconds)
show("Duration(seconds=1.5).to_msg()", lambda: Duration(seconds=1.5).to_msg())
show("Duration(seconds=2) * 1.5", lambda: Duration(seconds=2) * 1.5)
show("Duration(seconds=2) > Duration(seconds=1)", lambda: Duration(seconds=2) > Duration(seconds=1))
show("Duration(seconds=2) > 1", lambda: Duration(seconds=2) > 1)
show("Duration(seconds=2) + Duration(seconds=1)", lambda: Duration(seconds=2) + Duration(seconds=1))
show("Duration(seconds=2) - Duration(seconds=1)", lambda: Duration(seconds=2) - Duration(seconds=1))
show("(Time(seconds=3) - Time(seconds=1)).nanoseconds / 1e9",
     lambda: (Time(seconds=3) - Time(seconds=1)).nanoseconds / 1e9)
show("rclpy.timer.TimerInfo (Kilted only)", lambda: rclpy.timer.TimerInfo)
show("rclpy.ok() without init", rclpy.ok)
