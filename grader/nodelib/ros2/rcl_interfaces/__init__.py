"""ROS 2 rcl_interfaces interfaces (rosgrade's rosidl runtime)."""
