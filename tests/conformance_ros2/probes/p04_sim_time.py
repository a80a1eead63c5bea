#!/usr/bin/env python3
"""Probe 4: sim time under use_sim_time: now() before the first /clock, a timer made before it, create_rate, sleep_for.

Before any spin now() is 0 (the /clock subscription is only served while spinning). A 10 Hz timer created then
fires once as soon as sim time arrives, then on the 0.1 s grid counted from 0. A Rate in a second thread and
Clock.sleep_for follow sim time.
"""
import threading

import rclpy
from rclpy.duration import Duration
from rclpy.node import Node

GRID = 100_000_000


class Timing(Node):
    def __init__(self):
        super().__init__("p04_sim_time")
        print("use_sim_time", self.get_parameter("use_sim_time").value)
        print("now in __init__", self.get_clock().now())
        print("clock type", self.get_clock().clock_type)
        self.ticks = []
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self):
        self.ticks.append(self.get_clock().now().nanoseconds)


rclpy.init()
node = Timing()
print("now after __init__ (no spin yet)", node.get_clock().now().nanoseconds)
while len(node.ticks) < 5:
    rclpy.spin_once(node, timeout_sec=0.5)
t = node.ticks
print("#REF %.6f" % (t[0] / 1e9))
print("first tick has sim time", t[0] > 0)
print("second tick on the 0.1 s grid from 0", t[1] % GRID == 0, "and the next grid point", t[1] - t[0] <= GRID)
print("later ticks 0.1 s apart", [round((b - a) / 1e9, 3) for a, b in zip(t[1:], t[2:])])
node.destroy_timer(node.timer)

rate = node.create_rate(5)
stamps = []


def loop():
    for _ in range(4):
        rate.sleep()
        stamps.append(node.get_clock().now().nanoseconds)


thread = threading.Thread(target=loop)
start = node.get_clock().now().nanoseconds
thread.start()
while thread.is_alive():
    rclpy.spin_once(node, timeout_sec=0.05)
print("create_rate(5) first sleep within a period", 0 < stamps[0] - start <= 200_000_000 + 10_000_000)
print("create_rate(5) steps", [round((b - a) / 1e9, 2) for a, b in zip(stamps, stamps[1:])])

executor = rclpy.executors.SingleThreadedExecutor()
executor.add_node(node)
spinner = threading.Thread(target=executor.spin)
spinner.start()
before = node.get_clock().now()
print("sleep_for(0.3) returned", node.get_clock().sleep_for(Duration(seconds=0.3)))
advanced = (node.get_clock().now() - before).nanoseconds / 1e9
print("sleep_for(0.3) advanced about 0.3", 0.3 <= advanced < 0.33)
d = node.get_clock().now() - before
print("Time - Time is", type(d).__name__)
executor.shutdown()  # stop the spinning thread first: shutting rclpy down under it races (a traceback or an abort)
spinner.join()
rclpy.shutdown()
print("end")
