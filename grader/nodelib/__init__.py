"""Packages that student nodes import instead of a ROS install (rospy, genpy, messages, tf); see sitecustomize."""
