#!/usr/bin/env python3
"""A pure-Python busy loop that never calls the client library."""
import rospy
rospy.init_node("busy")
x = 0
while True:
    x += 1
