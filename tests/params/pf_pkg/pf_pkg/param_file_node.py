#!/usr/bin/env python3
"""Declares its parameters, prints what its parameter files gave them, and where the files are (its argv)."""
import sys

import rclpy
from rclpy.node import Node

rclpy.init()
node = Node("mover")
for name, default in (("speed", 0.1), ("name", "none"), ("waypoints", [0.0]), ("rate_hz", 1)):
    print(name, "=", repr(node.declare_parameter(name, default).value))
files = [sys.argv[i + 1] for i, arg in enumerate(sys.argv[:-1]) if arg == "--params-file"]
print("files", files)
node.destroy_node()
rclpy.shutdown()
