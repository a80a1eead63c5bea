#!/usr/bin/env python3
"""A Fibonacci action server whose goal callback never returns: the grader's goal is never accepted or rejected."""
import time

import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer
from rclpy.node import Node


def never(goal_request):
    while True:
        time.sleep(0.1)


rclpy.init()
node = Node("fibonacci_action_server")
ActionServer(node, Fibonacci, "fibonacci", lambda goal_handle: Fibonacci.Result(), goal_callback=never)
rclpy.spin(node)
