#!/usr/bin/env python3
"""An AddTwoInts server whose callback never returns (it sleeps in a loop): the grader's calls get no answer."""
import time

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node


def never(request, response):
    while True:
        time.sleep(0.1)


rclpy.init()
node = Node("add_two_ints_server")
node.create_service(AddTwoInts, "add_two_ints", never)
rclpy.spin(node)
