#!/usr/bin/env python3
"""The Fibonacci action server for grading a student's action client (the ROS 2 action tutorial's client): /fibonacci
with the submission's own Fibonacci action or example_interfaces', answering as the tutorial's server does (the
sequence so far as feedback after each new number, then the whole sequence), 0.2 s a step instead of the tutorial's
1 s, so what it sends is known in advance and the student's node must report it.

Usage: ``fibonacci_server.py <package>/action/<Name>``. Silent: what the run's log and /rosout hold is the student's.

Shipped with the grader and run confined like a student's node; never student code.
"""
import importlib
import sys
import time

import rclpy
from rclpy.action import ActionServer
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

STEP_S = 0.2


class FibonacciServer(Node):

    def __init__(self, action_type):
        super().__init__("fibonacci_action_server")
        self.action_type = action_type
        # example_interfaces' feedback field is `sequence`, the Jazzy tutorial's own action's `partial_sequence`
        (self.feedback_field,) = action_type.Feedback.get_fields_and_field_types()
        ActionServer(self, action_type, "fibonacci", self.execute)

    def execute(self, goal_handle):
        sequence = [0, 1]
        feedback = self.action_type.Feedback()
        for i in range(1, goal_handle.request.order):
            sequence.append(sequence[i] + sequence[i - 1])
            setattr(feedback, self.feedback_field, sequence)
            goal_handle.publish_feedback(feedback)
            time.sleep(STEP_S)
        goal_handle.succeed()
        return self.action_type.Result(sequence=sequence)


def main():
    package, _, name = sys.argv[1].split("/")
    action_type = getattr(importlib.import_module(f"{package}.action"), name)
    rclpy.init()
    try:
        rclpy.spin(FibonacciServer(action_type))
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or the end of the run: quietly, as the run's text is the student's


if __name__ == "__main__":
    main()
