"""The std_srvs ROS 1 package (services built from rosgrade's shared definitions)."""
