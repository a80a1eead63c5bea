#!/usr/bin/env python3
"""Probe 16: rclpy.action's graph queries in a node with an action server and an action client: the action names and
types on the graph, the ones a node serves and is a client of, and the error for a node that does not exist.

Fibonacci is example_interfaces' under rosgrade and test_msgs' under real rclpy: types are printed without their
package."""
import rclpy
from rclpy.action import (ActionClient, ActionServer, get_action_client_names_and_types_by_node,
                          get_action_names_and_types, get_action_server_names_and_types_by_node)
from rclpy.node import Node

try:
    from example_interfaces.action import Fibonacci
except ImportError:
    from test_msgs.action import Fibonacci


def shown(pairs):
    return [(name, [t.split("/", 1)[1] for t in types]) for name, types in pairs]


rclpy.init()
node = Node("p16_action_graph")
ActionServer(node, Fibonacci, "fib", lambda goal_handle: Fibonacci.Result())
ActionClient(node, Fibonacci, "other/fib2")
for _ in range(10):
    rclpy.spin_once(node, timeout_sec=0.05)
print("names", shown(get_action_names_and_types(node)))
print("served", shown(get_action_server_names_and_types_by_node(node, "p16_action_graph", "/")))
print("client of", shown(get_action_client_names_and_types_by_node(node, "p16_action_graph", "/")))
for query in (get_action_server_names_and_types_by_node, get_action_client_names_and_types_by_node):
    try:
        query(node, "nobody", "/")
    except Exception as exc:  # noqa: BLE001 - the probe prints what real rclpy raises
        print("unknown node !!", type(exc).__name__, exc)
print("end")
node.destroy_node()
rclpy.shutdown()
