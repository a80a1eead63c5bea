"""Probe: tf2_ros Buffer + TransformListener fed by /tf deliveries while spinning; lookup errors."""
import rclpy
from rclpy.node import Node
from rclpy.time import Time
from tf2_ros import Buffer, LookupException, TransformListener
from tf_transformations import euler_from_quaternion

rclpy.init()
node = Node("tf_user")
buffer = Buffer()
listener = TransformListener(buffer, node)
try:
    buffer.lookup_transform("odom", "base_footprint", Time())
except LookupException as exc:
    print("before:", exc)
for _ in range(80):
    rclpy.spin_once(node, timeout_sec=0.1)
t = buffer.lookup_transform("odom", "base_footprint", Time())
q = t.transform.rotation
print("after: x=%.3f yaw=%.3f stamp=%d" % (t.transform.translation.x, euler_from_quaternion([q.x, q.y, q.z, q.w])[2],
                                          t.header.stamp.sec))
