#!/usr/bin/env python3
"""Drives, and leaves a non-daemon thread running forever after the main thread returns."""
import threading
import time
import rospy
from geometry_msgs.msg import Twist

def forever():
    while True:
        time.sleep(1.0)

rospy.init_node("threads")
threading.Thread(target=forever).start()
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
rospy.sleep(0.5)
