#!/usr/bin/env python3
"""Starts a daemon that leaves the process group (setsid) with a cleared environment, then hangs."""
import os
import subprocess
import sys
import rospy
rospy.init_node("daemoniser")
subprocess.Popen([sys.executable, "-c", "import os,time\nos.setsid()\nwhile True: time.sleep(1)"],
                 env={}, start_new_session=True)
if os.fork() == 0:
    os.setsid()
    while True:
        pass
rospy.sleep(1.0)
