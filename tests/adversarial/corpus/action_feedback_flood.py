#!/usr/bin/env python3
"""A Fibonacci action server whose execute callback publishes feedback without end and never sleeps."""
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer
from rclpy.node import Node


def flood(goal_handle):
    feedback = Fibonacci.Feedback(sequence=list(range(100)))
    while True:
        goal_handle.publish_feedback(feedback)


rclpy.init()
node = Node("fibonacci_action_server")
ActionServer(node, Fibonacci, "fibonacci", flood)
rclpy.spin(node)
