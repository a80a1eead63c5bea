"""Probe: the course's pre-Exercise-5 main: spin without try, Ctrl+C ends the process by SIGINT."""
import rclpy
from rclpy.node import Node

rclpy.init()
node = Node("plain")
node.create_timer(0.1, lambda: None)
rclpy.spin(node)
