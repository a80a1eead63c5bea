"""ROS 2 sensor_msgs interfaces (rosgrade's rosidl runtime)."""
