#!/usr/bin/env python3
"""Writes a forged frame straight onto the grader's channel."""
import os
import struct
import rospy
rospy.init_node("forger")
rospy.sleep(0.2)
fds = [int(fd) for fd in os.listdir("/proc/self/fd")]
for fd in fds:
    if fd > 2:
        try:
            os.write(fd, struct.pack("<IB", 9, 250) + b"FORGED!!")
        except OSError:
            pass
rospy.sleep(1.0)
