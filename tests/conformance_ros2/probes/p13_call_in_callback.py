#!/usr/bin/env python3
"""Probe 13: Client.call inside a timer callback. In the node's default (mutually exclusive) group on a
single-threaded executor nothing takes the response while the callback waits: the call times out and returns
None (the classic deadlock, with a timeout so the probe ends; Jazzy's rclpy returns None where Kilted's raises
TimeoutError), nor on a MultiThreadedExecutor while the group is busy with the timer.
With the client and the timer in a reentrant group under a MultiThreadedExecutor another thread takes it and the call
returns. argv[1]: "single", "multi" (the default group) or "reentrant"."""
import sys
import threading

import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import SetBool

MODE = sys.argv[1] if len(sys.argv) > 1 else "single"
REENTRANT = MODE == "reentrant"
rclpy.init()
server = Node("p13_server")
server.create_service(SetBool, "/p13_switch", lambda request, response: SetBool.Response(success=request.data))
server_executor = SingleThreadedExecutor()
server_executor.add_node(server)


def serve():
    try:
        server_executor.spin()
    except ExternalShutdownException:
        pass  # rclpy.shutdown() at the end


threading.Thread(target=serve, daemon=True).start()

node = Node("p13_call_in_callback")
group = ReentrantCallbackGroup() if REENTRANT else None
client = node.create_client(SetBool, "/p13_switch", callback_group=group)
outcome = []


def tick():
    timer.cancel()
    print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
    response = client.call(SetBool.Request(data=True), timeout_sec=2.0)  # Jazzy: None once the timeout passes
    outcome.append("call returned None" if response is None else "call returned success %s" % response.success)


print("wait_for_service ->", client.wait_for_service(timeout_sec=10.0))
timer = node.create_timer(0.2, tick, callback_group=group)
executor = SingleThreadedExecutor() if MODE == "single" else MultiThreadedExecutor()
executor.add_node(node)
while not outcome:
    executor.spin_once(timeout_sec=0.1)
print(outcome[0])
rclpy.shutdown()
print("end")
