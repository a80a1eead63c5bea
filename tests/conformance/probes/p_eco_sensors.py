#!/usr/bin/env python3
"""Probe (issue 9 item 10): a TurtleBot3 in Gazebo publishes /imu, /joint_states and /scan besides /odom."""
import math

import rospy
from sensor_msgs.msg import Imu, JointState, LaserScan

rospy.init_node("eco_sensors")
imu = rospy.wait_for_message("/imu", Imu, timeout=5.0)
q = imu.orientation
print("imu", imu.header.frame_id, "unit", round(math.sqrt(q.x ** 2 + q.y ** 2 + q.z ** 2 + q.w ** 2), 6),
      round(imu.linear_acceleration.z, 2), "covariances zero", not any(imu.orientation_covariance))
joints = rospy.wait_for_message("/joint_states", JointState, timeout=5.0)
print("joint_states", list(joints.name), len(joints.position), len(joints.velocity), len(joints.effort),
      repr(joints.header.frame_id))
scan = rospy.wait_for_message("/scan", LaserScan, timeout=5.0)
print("scan", scan.header.frame_id, len(scan.ranges), scan.angle_min, round(scan.angle_max, 5),
      round(scan.angle_increment, 6), round(scan.range_min, 3), round(scan.range_max, 3), len(scan.intensities),
      "all inf", all(math.isinf(r) for r in scan.ranges), scan.time_increment, scan.scan_time)

counts = {"/imu": 0, "/joint_states": 0, "/scan": 0}
for topic, kind in (("/imu", Imu), ("/joint_states", JointState), ("/scan", LaserScan)):
    rospy.Subscriber(topic, kind, lambda msg, topic=topic: counts.__setitem__(topic, counts[topic] + 1))
rospy.sleep(2.0)
print("rates about 200, 30, 5 Hz", abs(counts["/imu"] - 400) <= 40, abs(counts["/joint_states"] - 60) <= 6,
      abs(counts["/scan"] - 10) <= 2)
