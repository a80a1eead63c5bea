#!/usr/bin/env python3
"""Probe 7: ROS 2 message classes: repr/str text, setters, constructor keywords, metadata, equality.

Since Jazzy, rosidl_python checks field types and constructor keywords only when ROS_PYTHON_CHECK_FIELDS=1 (or a
message is built with check_fields=True): by default a wrong value is stored as it is and fails when published.
The second half repeats the checks on messages built with check_fields=True, to pin the error texts.
"""
import array

from geometry_msgs.msg import Point, Pose, Quaternion, Twist, TwistStamped, Vector3
from nav_msgs.msg import Odometry
from std_msgs.msg import Header, String


def show(label, fn):
    try:
        value = fn()
        print(label, "->", repr(value), "(%s)" % type(value).__name__)
    except Exception as e:
        print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))


def setter(obj, path, value):
    *parents, last = path.split(".")
    target = obj
    for p in parents:
        target = getattr(target, p)
    setattr(target, last, value)
    return getattr(target, last)


show("Twist()", Twist)
show("str(Twist())", lambda: str(Twist()))
show("TwistStamped()", TwistStamped)
show("Header()", Header)
show("String(data='hi')", lambda: String(data="hi"))
show("Quaternion()", Quaternion)
show("Pose()", Pose)
show("Vector3(x=1.0, y=2.5)", lambda: Vector3(x=1.0, y=2.5))
show("Vector3(x=1)", lambda: Vector3(x=1))
show("Vector3(1.0, 2.0, 3.0)", lambda: Vector3(1.0, 2.0, 3.0))
show("Twist(foo=1)", lambda: Twist(foo=1))
show("Twist(linear=Vector3(x=0.2))", lambda: Twist(linear=Vector3(x=0.2)))
show("Twist(linear=Point())", lambda: Twist(linear=Point()))
t = Twist()
show("t.linear.x = 1", lambda: setter(t, "linear.x", 1))
show("t.linear.x = True", lambda: setter(t, "linear.x", True))
show("t.linear.x = '1'", lambda: setter(t, "linear.x", "1"))
show("t.linear.x = None", lambda: setter(t, "linear.x", None))
show("t.linear.x = 1e400", lambda: setter(t, "linear.x", 1e400))
show("t.linear.x = float('nan')", lambda: setter(t, "linear.x", float("nan")))
show("t.linear.x = 0.5", lambda: setter(t, "linear.x", 0.5))
show("t.linear = 5", lambda: setter(t, "linear", 5))
show("t.linear = Point()", lambda: setter(t, "linear", Point()))
show("t.foo = 1", lambda: setter(t, "foo", 1))
ts = TwistStamped()
show("ts.header.stamp.sec = 1.5", lambda: setter(ts, "header.stamp.sec", 1.5))
show("ts.header.stamp.sec = 2**31", lambda: setter(ts, "header.stamp.sec", 2 ** 31))
show("ts.header.stamp.nanosec = -1", lambda: setter(ts, "header.stamp.nanosec", -1))
show("ts.header.frame_id = 3", lambda: setter(ts, "header.frame_id", 3))
show("ts.header.frame_id = 'odom'", lambda: setter(ts, "header.frame_id", "odom"))
o = Odometry()
show("type(o.pose.covariance)", lambda: type(o.pose.covariance).__name__)
show("len(o.pose.covariance)", lambda: len(o.pose.covariance))
show("o.pose.covariance = [0.0] * 35", lambda: setter(o, "pose.covariance", [0.0] * 35))
show("o.pose.covariance = [1] * 36", lambda: setter(o, "pose.covariance", [1] * 36))
show("o.pose.covariance = [0.5] * 36 (type)", lambda: type(setter(o, "pose.covariance", [0.5] * 36)).__name__)
show("Twist.get_fields_and_field_types()", Twist.get_fields_and_field_types)
show("Odometry.get_fields_and_field_types()", Odometry.get_fields_and_field_types)
show("TwistStamped.__slots__", lambda: TwistStamped.__slots__)
show("Twist() == Twist()", lambda: Twist() == Twist())
show("Twist() == Vector3()", lambda: Twist() == Vector3())
show("Vector3(x=1.0) == Vector3()", lambda: Vector3(x=1.0) == Vector3())
show("hash(Twist())", lambda: hash(Twist()))
show("Twist.__module__", lambda: Twist.__module__)
show("type(Twist).__name__", lambda: type(Twist).__name__)
show("array check", lambda: isinstance(o.pose.covariance, array.array))

print("ROS_PYTHON_CHECK_FIELDS", repr(__import__("os").environ.get("ROS_PYTHON_CHECK_FIELDS")))
show("Twist(foo=1, check_fields=True)", lambda: Twist(foo=1, check_fields=True))
show("Vector3(x=1, check_fields=True)", lambda: Vector3(x=1, check_fields=True))
c = Twist(check_fields=True)
show("checked t.linear.x = 1", lambda: setter(c, "linear.x", 1))
show("checked t.linear.x = '1'", lambda: setter(c, "linear.x", "1"))
show("checked t.linear.x = 1e400", lambda: setter(c, "linear.x", 1e400))
show("checked t.linear = 5", lambda: setter(c, "linear", 5))
show("checked t.linear = Point()", lambda: setter(c, "linear", Point()))
show("checked t.linear.x after", lambda: c.linear.x)
cs = TwistStamped(check_fields=True)
show("checked ts.header.stamp.sec = 1.5", lambda: setter(cs, "header.stamp.sec", 1.5))
show("checked ts.header.frame_id = 3", lambda: setter(cs, "header.frame_id", 3))
co = Odometry(check_fields=True)
show("checked o.pose.covariance = [0.0] * 35", lambda: setter(co, "pose.covariance", [0.0] * 35))
