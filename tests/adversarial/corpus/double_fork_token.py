#!/usr/bin/env python3
"""Double-forks a daemon with an empty environment (no marker) that would outlive the run, then exits at once."""
import os
import sys
import rospy
rospy.init_node("outliver")
if os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        os.execve(sys.executable, [sys.executable, "-c", "import time\nwhile True: time.sleep(1)", sys.argv[1]], {})
    os._exit(0)
print("parent leaving")
