"""Client.call from a timer callback: under a MultiThreadedExecutor with a reentrant group it returns; in the node's
default (mutually exclusive) group on a single-threaded executor it never does (the classic deadlock)."""
import sys

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node

REENTRANT = sys.argv[1] == "reentrant"


class Caller(Node):
    def __init__(self):
        super().__init__("caller")
        group = ReentrantCallbackGroup() if REENTRANT else None
        self.client = self.create_client(AddTwoInts, "add_two_ints", callback_group=group)
        self.timer = self.create_timer(0.5, self.tick, callback_group=group)

    def tick(self):
        self.timer.cancel()
        self.client.wait_for_service()
        print("calling", flush=True)
        response = self.client.call(AddTwoInts.Request(a=1, b=2))
        print(f"returned {response.sum}", flush=True)


rclpy.init()
executor = MultiThreadedExecutor() if REENTRANT else SingleThreadedExecutor()
executor.add_node(Caller())
executor.spin()
