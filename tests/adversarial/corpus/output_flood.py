#!/usr/bin/env python3
import rospy
rospy.init_node("flood")
while True:
    print("spam " * 40)
