"""ROS 2 builtin_interfaces interfaces (rosgrade's rosidl runtime)."""
