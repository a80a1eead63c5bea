"""ROS 2 std_msgs interfaces (rosgrade's rosidl runtime)."""
