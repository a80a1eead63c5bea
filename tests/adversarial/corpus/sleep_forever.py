#!/usr/bin/env python3
import time
import rospy
rospy.init_node("sleeper")
time.sleep(10**6)
