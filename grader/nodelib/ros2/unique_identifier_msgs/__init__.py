"""ROS 2 unique_identifier_msgs interfaces (rosgrade's rosidl runtime): UUID, an action goal's id."""
