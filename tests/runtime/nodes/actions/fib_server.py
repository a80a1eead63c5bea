"""The ROS 2 action tutorial's Fibonacci server: a feedback every 0.5 s; with ``cancel``, a MultiThreadedExecutor and
a reentrant group let it accept a cancel while it executes, and it ends the goal CANCELED."""
import sys
import time

import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer, CancelResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node

CANCELS = sys.argv[1:] == ["cancel"]


class Server(Node):
    def __init__(self):
        super().__init__("fibonacci_action_server")
        extra = dict(callback_group=ReentrantCallbackGroup(), cancel_callback=lambda _: CancelResponse.ACCEPT) \
            if CANCELS else {}
        self._server = ActionServer(self, Fibonacci, "fibonacci", self.execute_callback, **extra)

    def now(self):
        return self.get_clock().now().nanoseconds

    def execute_callback(self, goal_handle):
        print(f"executing order {goal_handle.request.order} at {self.now()}", flush=True)
        feedback = Fibonacci.Feedback()
        feedback.sequence = [0, 1]
        for i in range(1, goal_handle.request.order):
            if goal_handle.is_cancel_requested:
                goal_handle.canceled()
                print(f"canceled at {self.now()}", flush=True)
                return Fibonacci.Result(sequence=feedback.sequence)
            feedback.sequence.append(feedback.sequence[i] + feedback.sequence[i - 1])
            goal_handle.publish_feedback(feedback)
            time.sleep(0.5)
        goal_handle.succeed()
        print(f"succeeded at {self.now()}", flush=True)
        return Fibonacci.Result(sequence=feedback.sequence)


rclpy.init()
node = Server()
if CANCELS:
    rclpy.spin(node, executor=MultiThreadedExecutor())
else:
    rclpy.spin(node)
