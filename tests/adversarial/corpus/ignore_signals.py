#!/usr/bin/env python3
"""Ignores Ctrl+C and SIGTERM and loops forever, publishing (so it yields to the grader)."""
import signal
import rospy
from geometry_msgs.msg import Twist

signal.signal(signal.SIGTERM, signal.SIG_IGN)
rospy.init_node("stubborn", disable_signals=True)
signal.signal(signal.SIGINT, signal.SIG_IGN)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
while True:
    try:
        pub.publish(Twist())
        rospy.sleep(0.1)
    except BaseException:
        pass
