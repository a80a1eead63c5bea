"""Hostile: ask the run's graph without end, as fast as the node can, while another node holds 900 publishers."""
import rclpy
from rclpy.node import Node

rclpy.init()
node = Node("graph_asker")
asked = 0
while True:
    node.get_topic_names_and_types()
    node.count_publishers("/flood/t0")
    asked += 2
    if asked % 1000 == 0:
        print("asked", asked, flush=True)
