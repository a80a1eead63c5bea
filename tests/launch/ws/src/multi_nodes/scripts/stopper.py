#!/usr/bin/env python3
"""Sleeps for argv[1] sim seconds, then exits: as a required node, it ends the launch."""
import sys

import rospy

rospy.init_node("stopper")
rospy.sleep(float(sys.argv[1]))
print("stopper done")
