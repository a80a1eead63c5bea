#!/usr/bin/env python3
"""Probe 8: using rclpy before init and after shutdown; ends with the uncaught NotInitializedException (exit 1)."""
import rclpy
from rclpy.node import Node


def show(label, fn):
    try:
        value = fn()
        print(label, "->", repr(value))
    except Exception as e:
        print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))


show("rclpy.ok()", rclpy.ok)
show("rclpy.shutdown() before init", rclpy.shutdown)
show("rclpy.try_shutdown() before init", rclpy.try_shutdown)
show("Node('x') before init", lambda: Node("x"))
show("rclpy.create_node('x') before init", lambda: rclpy.create_node("x"))
rclpy.init()
show("rclpy.init() twice", rclpy.init)
show("Node('bad name')", lambda: Node("bad name"))
show("Node('x', namespace='bad ns')", lambda: Node("x", namespace="bad ns"))
node = Node("p08_not_initialized")
show("node.get_name()", node.get_name)
show("node.get_namespace()", node.get_namespace)
show("node.get_fully_qualified_name()", node.get_fully_qualified_name)
show("create_publisher without qos", lambda: node.create_publisher(rclpy.node.Parameter, "/x"))
show("node.__enter__() (a Node as a context manager: Kilted only)", lambda: node.__enter__())
rclpy.shutdown()
show("rclpy.ok() after shutdown", rclpy.ok)
show("create_timer after shutdown", lambda: node.create_timer(0.1, lambda: None))
show("Node('y') after shutdown", lambda: Node("y"))
show("rclpy.init() after shutdown", rclpy.init)
show("rclpy.shutdown() again", rclpy.shutdown)
show("rclpy.shutdown() a second time", rclpy.shutdown)
Node("after_shutdown")
print("not reached")
