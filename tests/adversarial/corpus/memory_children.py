#!/usr/bin/env python3
"""Forks children that each hold 150 MB (within the per-process limit) and keep it; the parent carries on."""
import os
import signal
import rospy
rospy.init_node("hoarder")
for _ in range(3):
    if os.fork() == 0:
        hoard = b"x" * (150 << 20)
        signal.pause()
while not rospy.is_shutdown():
    rospy.sleep(0.001)
