"""Hostile's partner: hold 900 publishers (under the endpoint limit), so every graph view is large, and spin."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String

rclpy.init()
node = Node("graph_holder")
publishers = [node.create_publisher(String, "/flood/t%d" % i, 1) for i in range(900)]
rclpy.spin(node)
