"""The ROS 1 client library root (rospy, genpy, message packages, tf): on a ROS 1 node's import path."""
