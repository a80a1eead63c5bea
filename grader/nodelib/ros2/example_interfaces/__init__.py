"""ROS 2 example_interfaces interfaces (rosgrade's rosidl runtime): AddTwoInts, the service tutorial's."""
