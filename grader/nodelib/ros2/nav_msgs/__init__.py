"""ROS 2 nav_msgs interfaces (rosgrade's rosidl runtime)."""
