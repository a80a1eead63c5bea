"""ROS 2 service_msgs interfaces (rosgrade's rosidl runtime)."""
