"""The actionlib_msgs ROS 1 package (GoalID, GoalStatus, GoalStatusArray, built from rosgrade's shared definitions)."""
