"""ROS 2 example_interfaces interfaces (rosgrade's rosidl runtime): AddTwoInts and Fibonacci, the service and action tutorials'."""
