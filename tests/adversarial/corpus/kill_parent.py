#!/usr/bin/env python3
import os
import signal
import rospy
rospy.init_node("parricide")
for target in (os.getppid(), 1):
    try:
        os.kill(target, signal.SIGKILL)
        print(f"killed {target}")
    except OSError as exc:
        print(f"kill {target}: {exc}")
rospy.sleep(1.0)
print("still here")
