#!/usr/bin/env python3
import rospy
rospy.init_node("hog")
blocks = []
while True:
    blocks.append(bytearray(16 << 20))
