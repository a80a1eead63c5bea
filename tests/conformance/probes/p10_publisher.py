#!/usr/bin/env python3
"""Probe 10: a student-style 10 Hz /cmd_vel publisher for 2 s of sim time (linear.z carries the iteration)."""
import rospy
from geometry_msgs.msg import Twist

rospy.init_node("p10_publisher")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rate = rospy.Rate(10)
T0 = None
i = 0
while not rospy.is_shutdown() and i < 23:
    now = rospy.get_time()
    if T0 is None and now > 0:
        T0 = now
        print("#REF %.6f" % T0)
    t = Twist()
    t.linear.x = 0.1
    t.angular.z = 0.2
    t.linear.z = i
    pub.publish(t)
    print("published", i, "t=zero" if now == 0 else "t=%.3f" % (now - T0))
    i += 1
    rate.sleep()
print("connections", pub.get_num_connections())
