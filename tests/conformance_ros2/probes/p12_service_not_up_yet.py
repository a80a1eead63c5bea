#!/usr/bin/env python3
"""Probe 12: a call made before any server exists is never answered, not even once a server appears; a call made
after wait_for_service is answered."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import SetBool

rclpy.init()
node = Node("p12_service_not_up_yet")
server = Node("p12_server")
client = node.create_client(SetBool, "/p12_switch")
executor = SingleThreadedExecutor()
executor.add_node(node)
executor.add_node(server)
while node.get_clock().now().nanoseconds == 0:
    executor.spin_once(timeout_sec=0.01)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
early = client.call_async(SetBool.Request(data=True))
executor.spin_until_future_complete(early, timeout_sec=0.5)
print("early call done with no server", early.done())
server.create_service(SetBool, "/p12_switch", lambda request, response: SetBool.Response(success=True))
print("wait_for_service ->", client.wait_for_service(timeout_sec=10.0))
executor.spin_until_future_complete(early, timeout_sec=1.0)
print("early call done once the server is up", early.done())
late = client.call_async(SetBool.Request(data=True))
executor.spin_until_future_complete(late, timeout_sec=5.0)
print("later call done", late.done(), "success", late.done() and late.result().success)
rclpy.shutdown()
print("end")
