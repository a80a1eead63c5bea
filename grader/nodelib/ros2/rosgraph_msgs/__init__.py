"""ROS 2 rosgraph_msgs interfaces (rosgrade's rosidl runtime)."""
