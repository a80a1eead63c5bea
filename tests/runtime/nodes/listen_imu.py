#!/usr/bin/env python3
"""Subscribes to /imu and /joint_states (not /scan) and counts what arrives, printing the counts at Ctrl+C."""
import rospy
from sensor_msgs.msg import Imu, JointState

counts = {"imu": 0, "joint_states": 0}


def count(key):
    def callback(_msg):
        counts[key] += 1
    return callback


rospy.init_node("listen_imu")
rospy.Subscriber("/imu", Imu, count("imu"))
rospy.Subscriber("/joint_states", JointState, count("joint_states"))
rospy.on_shutdown(lambda: print("received", counts["imu"], counts["joint_states"]))
rospy.spin()
