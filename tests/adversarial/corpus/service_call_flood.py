#!/usr/bin/env python3
"""Calls its own service without end from its main loop (no spinning in between): each call costs sim time."""
import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node

rclpy.init()
node = Node("flood")
node.create_service(AddTwoInts, "add_two_ints", lambda request, response: response)
client = node.create_client(AddTwoInts, "add_two_ints")
calls = 0
while True:
    client.call_async(AddTwoInts.Request(a=calls, b=1))
    calls += 1
    if calls % 1000 == 0:
        print("calls", calls, flush=True)
