"""Probe: a timer callback that blocks starves the single-threaded executor (odom and the clock stop)."""
import time

import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class Starver(Node):
    def __init__(self):
        super().__init__("starver")
        self.odoms = 0
        self.create_subscription(Odometry, "odom", self.on_odom, 10)
        self.create_timer(0.1, self.tick)

    def on_odom(self, msg):
        self.odoms += 1

    def tick(self):
        start = self.get_clock().now()
        while self.odoms < 3:
            time.sleep(0.1)
            print(f"waiting odoms={self.odoms} clock_moved={self.get_clock().now() != start}")


rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
node = Starver()
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    print("interrupted in", "sleep")
