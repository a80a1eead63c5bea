"""The tf2_msgs ROS 1 package (messages built from rosgrade's shared definitions)."""
