"""ROS 2 std_srvs interfaces (rosgrade's rosidl runtime)."""
