"""ROS 2 turtlesim interfaces (rosgrade's rosidl runtime): Pose, Color, its services and RotateAbsolute."""
