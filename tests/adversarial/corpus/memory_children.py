#!/usr/bin/env python3
"""Forks children that each hold 150 MB (within the per-process limit) and keep it; the parent carries on, or with
`hang` blocks outside the client library, never yielding to the grader again."""
import os
import signal
import sys
import rospy
rospy.init_node("hoarder")
for _ in range(3):
    if os.fork() == 0:
        hoard = b"x" * (150 << 20)
        signal.pause()
if "hang" in sys.argv[1:]:
    read_end, _write_end = os.pipe()
    os.read(read_end, 1)  # nobody ever writes
while not rospy.is_shutdown():
    rospy.sleep(0.001)
