#!/usr/bin/env python3
import os
import signal
import rospy
rospy.init_node("groupkill")
rospy.sleep(0.5)
os.killpg(0, signal.SIGKILL)
