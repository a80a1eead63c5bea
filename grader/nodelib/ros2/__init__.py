"""The ROS 2 client library root (rclpy, the rosidl message runtime, message packages, tf2_ros): on a ROS 2 node's
import path."""
