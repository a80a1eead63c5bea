#!/usr/bin/env python3
"""Probe 33 (issue 33 item 2): when a publisher connects to the robot while the node waits for it without ever
blocking (a busy loop), and while it polls with rospy.sleep.

Real rospy's threads that answer the robot's connection (requestTopic, the TCPROS header) need the GIL, which a busy
main thread hands over only every 5 ms: busy, the connection comes later. Argument: ``busy`` or ``sleep``.
"""
import sys

import rospy
from geometry_msgs.msg import Twist

mode = sys.argv[1]
rospy.init_node("p33_busy_connect")
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
print("connections at creation", pub.get_num_connections())
while pub.get_num_connections() == 0:
    if mode == "sleep":
        rospy.sleep(0.001)
print("%s wait for the robot ended t=%.3f" % (mode, rospy.get_time() - T0))
cmd = Twist()
cmd.linear.x = 0.2
pub.publish(cmd)
rospy.sleep(0.5)
print("end")
