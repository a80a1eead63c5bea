#!/usr/bin/env python3
import rospy
rospy.init_node("recurse")

def down(n):
    return down(n + 1) + 1

down(0)
