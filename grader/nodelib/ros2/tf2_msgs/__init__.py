"""ROS 2 tf2_msgs interfaces (rosgrade's rosidl runtime)."""
