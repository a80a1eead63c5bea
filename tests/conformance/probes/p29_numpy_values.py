#!/usr/bin/env python3
"""Probe 29 (issue 9 item 7): more numpy values in message fields on subscribed topics: what publishes, what raises.

(Not here: a publish that raises on a connected topic leaves real rospy's buffer half written, so the next message
on that publisher is lost: below, nothing is published on a publisher after one of its publishes failed.)"""
import numpy as np
import rospy
from geometry_msgs.msg import Twist, Vector3
from std_msgs.msg import Int32, String

rospy.init_node("p29_numpy_values")
pubs = {"/p29_twist": rospy.Publisher("/p29_twist", Twist, queue_size=10),
        "/p29_int": rospy.Publisher("/p29_int", Int32, queue_size=10),
        "/p29_str": rospy.Publisher("/p29_str", String, queue_size=10)}
got = []
rospy.Subscriber("/p29_twist", Twist, lambda m: got.append(("twist", m.linear.x, type(m.linear.x).__name__)))
rospy.Subscriber("/p29_int", Int32, lambda m: got.append(("int", m.data, type(m.data).__name__)))
rospy.Subscriber("/p29_str", String, lambda m: got.append(("str", m.data, type(m.data).__name__)))
rospy.sleep(0.5)


def attempt(label, topic, msg):
    try:
        pubs[topic].publish(msg)
        print(label, "published")
    except Exception as e:
        print(label, "!!", type(e).__name__, str(e).splitlines()[0][:120])


attempt("Twist linear.x=np.int64(2)", "/p29_twist", Twist(linear=Vector3(x=np.int64(2))))
attempt("Int32 data=np.int64(7)", "/p29_int", Int32(data=np.int64(7)))
attempt("Int32 data=np.float64(7.0)", "/p29_int", Int32(data=np.float64(7.0)))
attempt("Int32 data=7.5", "/p29_int", Int32(data=7.5))
attempt("String data=np.str_('hi')", "/p29_str", String(data=np.str_("hi")))
rospy.sleep(0.3)
print("received", sorted(got))
