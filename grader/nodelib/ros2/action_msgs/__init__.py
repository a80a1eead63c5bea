"""ROS 2 action_msgs interfaces (rosgrade's rosidl runtime): goal status and the cancel service of every action."""
