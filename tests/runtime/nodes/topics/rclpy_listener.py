#!/usr/bin/env python3
# Hears /chatter from 0.5 s after it starts: prints each message with the node's time.
import time

import rclpy
from rclpy.node import Node
from std_msgs.msg import String

rclpy.init()
node = Node("listener")
time.sleep(0.5)
node.create_subscription(
    String, "/chatter",
    lambda msg: print(f"heard {msg.data} {node.get_clock().now().nanoseconds / 1e9:.3f}", flush=True), 10)
rclpy.spin(node)
