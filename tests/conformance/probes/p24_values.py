#!/usr/bin/env python3
"""Probe 24 (issue 9 item 7): numpy values in float fields, Time(0, 5e8), bad data on an unsubscribed topic."""
import numpy as np
import rospy
from geometry_msgs.msg import PoseStamped, Twist

rospy.init_node("p24_values")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
debug = rospy.Publisher("/p24_debug", Twist, queue_size=10)
stamped = rospy.Publisher("/p24_pose", PoseStamped, queue_size=10)
received = []
rospy.Subscriber("/p24_pose", PoseStamped, lambda m: received.append(m.header.stamp))
rospy.sleep(0.5)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
t = rospy.Time(0, 5e8)
print("Time(0, 5e8)", t.secs, t.nsecs, type(t.nsecs).__name__)
d = rospy.Duration(1, 2.5e8)
print("Duration(1, 2.5e8)", d.secs, d.nsecs, type(d.nsecs).__name__)
pose = PoseStamped()
pose.header.stamp = t
stamped.publish(pose)
print("published a header stamped Time(0, 5e8)")
cmd = Twist()
cmd.linear.x = np.float64(0.1)
cmd.linear.y = np.float32(0.0)
cmd.angular.z = np.array([0.2])
pub.publish(cmd)
print("published numpy scalar and 1-element array values")
bad = Twist()
bad.linear.x = "fast"
debug.publish(bad)
print("bad value on an unsubscribed topic: no error")
rospy.sleep(0.3)
print("stamp received", [(s.secs, s.nsecs) for s in received])
try:
    pub.publish(bad)
    print("bad value on /cmd_vel published")
except rospy.ROSSerializationException as e:
    print("bad value on /cmd_vel !! %s: %s" % (type(e).__name__, e))
