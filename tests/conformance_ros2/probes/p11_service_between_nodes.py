#!/usr/bin/env python3
"""Probe 11: a service call between two nodes (one process, one executor): wait_for_service sees the server once it
exists, call_async gets each response, and the response comes back within the same sim-clock tick or the next one.

Real ROS 2 answers in about a millisecond of wall time (printed as a volatile latency line, for the record).
"""
import time

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import SetBool


def handle(request, response):
    response.success = request.data
    response.message = "set %s" % request.data
    return response


rclpy.init()
node = Node("p11_service_between_nodes")
server = Node("p11_server")
client = node.create_client(SetBool, "/p11_switch")
print("ready before the server exists", client.service_is_ready())
executor = SingleThreadedExecutor()
executor.add_node(node)
executor.add_node(server)
while node.get_clock().now().nanoseconds == 0:
    executor.spin_once(timeout_sec=0.01)
server.create_service(SetBool, "/p11_switch", handle)
waited, wall = node.get_clock().now().nanoseconds, time.monotonic()
print("wait_for_service ->", client.wait_for_service(timeout_sec=10.0))
print("discovery wall ms %.2f sim ms %.1f" % ((time.monotonic() - wall) * 1e3,
                                              (node.get_clock().now().nanoseconds - waited) / 1e6))
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
for data in (True, False):
    sent, wall = node.get_clock().now().nanoseconds, time.monotonic()
    future = client.call_async(SetBool.Request(data=data))
    executor.spin_until_future_complete(future, timeout_sec=5.0)
    elapsed = node.get_clock().now().nanoseconds - sent
    print("response", future.result().success, future.result().message)
    print("answered within one clock tick", elapsed <= 10_000_000)
    print("latency wall ms %.2f sim ms %.1f" % ((time.monotonic() - wall) * 1e3, elapsed / 1e6))
rclpy.shutdown()
print("end")
