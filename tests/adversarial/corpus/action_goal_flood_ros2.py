#!/usr/bin/env python3
"""An rclpy node with an ActionServer whose goals never end and an ActionClient sending it goals without end: each
goal is a send_goal call, and the server's status array (every goal, on each change) grows."""
import time

import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient, ActionServer
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node


def forever(goal_handle):
    while True:
        time.sleep(1.0)


rclpy.init()
node = Node("goal_flood")
ActionServer(node, Fibonacci, "flood", forever, callback_group=ReentrantCallbackGroup())
client = ActionClient(node, Fibonacci, "flood")
executor = MultiThreadedExecutor()
executor.add_node(node)
client.wait_for_server()
sent = 0
while rclpy.ok():
    client.send_goal_async(Fibonacci.Goal(order=sent))
    sent += 1
    executor.spin_once(timeout_sec=0)
    if sent % 100 == 0:
        print("goals", sent, flush=True)
