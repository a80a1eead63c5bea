"""The turtlesim ROS 1 package (messages built from rosgrade's shared definitions)."""
