"""ROS 2 geometry_msgs interfaces (rosgrade's rosidl runtime)."""
