#!/usr/bin/env python3
"""Writes 64 MB into /dev/shm under a name the test gives, to fill the host's shared memory."""
import sys
import rospy
rospy.init_node("shm_filler")
written = 0
try:
    with open(f"/dev/shm/{sys.argv[1]}", "wb") as handle:
        for _ in range(64):
            handle.write(b"x" * (1 << 20))
            handle.flush()
            written += 1
except OSError as exc:
    print(f"stopped after {written} MB: {exc.strerror}")
else:
    print(f"wrote {written} MB")
