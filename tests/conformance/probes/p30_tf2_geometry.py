#!/usr/bin/env python3
"""Probe 30 (issue 9 item 5): tf2_geometry_msgs.do_transform_* on a stamped point, vector, pose and pose-with-
covariance, through a transform that both rotates (90° about z) and translates: what nodes do with a tf2 lookup."""
import math

import rospy
import tf2_geometry_msgs
from geometry_msgs.msg import PointStamped, PoseStamped, TransformStamped, Vector3Stamped

rospy.init_node("p30_tf2_geometry")
t = TransformStamped()
t.header.frame_id, t.child_frame_id = "odom", "base_footprint"
t.header.stamp = rospy.Time(12, 500)
t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = 1.0, 2.0, 0.5
t.transform.rotation.z, t.transform.rotation.w = math.sin(math.pi / 4), math.cos(math.pi / 4)


def r(*values):
    return [round(v, 6) + 0.0 for v in values]


point = PointStamped()
point.header.frame_id = "base_footprint"
point.point.x, point.point.y, point.point.z = 1.0, 0.0, 0.25
out = tf2_geometry_msgs.do_transform_point(point, t)
print("point", out.header.frame_id, out.header.stamp.secs, out.header.stamp.nsecs, r(out.point.x, out.point.y, out.point.z))

vector = Vector3Stamped()
vector.vector.x, vector.vector.y = 1.0, 2.0
out = tf2_geometry_msgs.do_transform_vector3(vector, t)
print("vector", out.header.frame_id, r(out.vector.x, out.vector.y, out.vector.z))

pose = PoseStamped()
pose.pose.position.x = 2.0
pose.pose.orientation.z, pose.pose.orientation.w = math.sin(math.pi / 8), math.cos(math.pi / 8)
out = tf2_geometry_msgs.do_transform_pose(pose, t)
q = out.pose.orientation
print("pose", out.header.frame_id, r(out.pose.position.x, out.pose.position.y, out.pose.position.z),
      "yaw deg", round(math.degrees(math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))), 6))
print("types", type(out).__name__, type(tf2_geometry_msgs.do_transform_point(point, t)).__name__)
