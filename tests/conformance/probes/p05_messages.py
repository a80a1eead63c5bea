#!/usr/bin/env python3
"""Probe 5: message classes (genpy semantics): constructors, defaults, str(), errors, __slots__, equality, md5s."""
import io

from geometry_msgs.msg import Point, Pose, Quaternion, TransformStamped, Twist, Vector3
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64, Header, Int32, String
from tf2_msgs.msg import TFMessage


def err(e):
    return "%s.%s: %s" % (type(e).__module__, type(e).__name__, e)


def show(label, fn):
    try:
        value = fn()
        print(label, "->", "%r (%s)" % (value, type(value).__name__) if not isinstance(value, str) else repr(value))
    except Exception as e:
        print(label, "!!", err(e))


def serialize(msg):
    buf = io.BytesIO()
    msg.serialize(buf)
    return buf.getvalue()


for cls in (Twist, Vector3, Odometry, TFMessage, String, Float64, Int32, Quaternion, Header, Pose, TransformStamped):
    print("meta", cls.__name__, cls._type, cls._md5sum, cls._has_header, cls.__slots__, cls._slot_types)
    # rosgrade's _full_text is the comment-free canonical definition (same md5sum; ROS's comments are not copied),
    # so compare its structure: which dependency definitions it carries.
    print("full_text_deps", cls.__name__, sorted(line for line in cls._full_text.splitlines() if line.startswith("MSG: ")))

show("Twist(Vector3(1,2,3), Vector3(4,5,6))", lambda: Twist(Vector3(1, 2, 3), Vector3(4, 5, 6)).linear.y)
show("Twist(Vector3(1,0,0))", lambda: Twist(Vector3(1, 0, 0)))
show("Twist(Vector3(), angular=Vector3())", lambda: Twist(Vector3(), angular=Vector3()))
show("Twist(foo=1)", lambda: Twist(foo=1))
show("Vector3(1,2)", lambda: Vector3(1, 2))
show("Vector3(x=1).y", lambda: Vector3(x=1).y)
show("Float64(3).data", lambda: Float64(3).data)
show("String().data", lambda: String().data)
show("Quaternion()", lambda: (Quaternion().x, Quaternion().y, Quaternion().z, Quaternion().w))
show("Odometry().pose.covariance", lambda: Odometry().pose.covariance)
show("type(Odometry().pose.covariance)", lambda: type(Odometry().pose.covariance).__name__)
show("Odometry().header.stamp", lambda: Odometry().header.stamp)
show("TFMessage().transforms", lambda: TFMessage().transforms)
show("Twist().linear.x", lambda: Twist().linear.x)
show("hasattr(Twist(), '__dict__')", lambda: hasattr(Twist(), "__dict__"))


def set_foo():
    t = Twist()
    t.foo = 1


show("t.foo = 1", set_foo)


def set_linear():
    t = Twist()
    t.linear = 5
    return t.linear


show("t.linear = 5", set_linear)
show("Twist() == Twist()", lambda: Twist() == Twist())
show("Vector3(1,0,0) == Vector3(1.0,0,0)", lambda: Vector3(1, 0, 0) == Vector3(1.0, 0, 0))
show("Twist() == 0", lambda: Twist() == 0)
show("Twist() != Twist()", lambda: Twist() != Twist())
show("hash(Twist())", lambda: hash(Twist()))
show("Twist(linear=Vector3(1,0,0)) == Twist()", lambda: Twist(linear=Vector3(1, 0, 0)) == Twist())

print("str(Twist()):")
print(str(Twist()))
print("repr equals str", repr(Twist()) == str(Twist()))
v = Vector3(0.1, 1e-20, 1 / 3.0)
print("str(Vector3(0.1, 1e-20, 1/3)):")
print(v)
print("str(Vector3(1,2,3)):")
print(Vector3(1, 2, 3))
print("str(String('hi')):", str(String("hi")))
print("str(String()):", str(String()))
odom = Odometry()
odom.header.seq = 7
odom.header.stamp.secs = 12
odom.header.stamp.nsecs = 500000000
odom.header.frame_id = "odom"
odom.child_frame_id = "base_footprint"
odom.pose.pose.position.x = 1.5
odom.twist.twist.linear.x = 0.2
print("str(odom):")
print(odom)
print("str(Odometry()) header:")
print(str(Odometry()).split("child_frame_id")[0], end="")
tfm = TFMessage(transforms=[TransformStamped(), TransformStamped()])
tfm.transforms[0].child_frame_id = "a"
print("str(TFMessage 2):")
print(tfm)
print("str(Header()):")
print(Header())

# Serialization: what publish() does when a subscriber is connected.
t = Twist()
t.linear.x = 0.5
t.angular.z = -1.25
data = serialize(t)
print("twist bytes", len(data), data.hex())
back = Twist()
back.deserialize(data)
print("roundtrip equal", back == t, back.angular.z)
for label, value in [("'fast'", "fast"), ("None", None), ("'0.5'", "0.5"), ("[1]", [1]), ("1j", 1j),
                     ("int 2", 2), ("True", True), ("1e400", 1e400), ("nan", float("nan"))]:
    bad = Twist()
    bad.linear.x = value
    show("serialize linear.x=" + label, lambda: len(serialize(bad)))
show("serialize String(data=5)", lambda: len(serialize(String(data=5))))
show("serialize Int32(2**40)", lambda: len(serialize(Int32(2 ** 40))))
show("serialize Int32(1.5)", lambda: len(serialize(Int32(1.5))))
show("serialize t.linear=None", lambda: len(serialize(Twist(linear=None, angular=Vector3()))))
o = Odometry()
o.header.stamp.secs = 3
o.pose.covariance = [0.0] * 35
show("serialize covariance 35", lambda: len(serialize(o)))
o.pose.covariance = tuple([1.0] * 36)
show("serialize covariance tuple 36", lambda: len(serialize(o)))
show("Odometry size", lambda: len(serialize(Odometry())))
p = Point(1, 2, 3)
show("Pose(position=p).position is p", lambda: Pose(position=p).position is p)
