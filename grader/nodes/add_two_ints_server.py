#!/usr/bin/env python3
"""The AddTwoInts server for grading a student's service client (the ROS 2 service tutorial's client): /add_two_ints
(example_interfaces/srv/AddTwoInts) answering sum = a + b, as the tutorial's server does, so that what it answers is
known in advance and the student's node must report it.

Silent: what the run's log and /rosout hold is the student's node's.

Shipped with the grader and run confined like a student's node; never student code.
"""
import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node


def add(request, response):
    response.sum = request.a + request.b
    return response


def main():
    rclpy.init()
    node = Node("add_two_ints_server")
    node.create_service(AddTwoInts, "add_two_ints", add)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or the end of the run: quietly, as the run's text is the student's


if __name__ == "__main__":
    main()
