#!/usr/bin/env python3
"""Forks children that spin forever, each below the per-process CPU limit for a while; the parent carries on."""
import os
import rospy
rospy.init_node("spinner")
for _ in range(4):
    if os.fork() == 0:
        while True:
            pass
while not rospy.is_shutdown():
    rospy.sleep(0.001)
