"""Graph test node: prints what the graph shows of the other node, the world and itself every 0.25 s."""
import rclpy
from rclpy.action import get_action_names_and_types, get_action_server_names_and_types_by_node
from rclpy.node import Node
from geometry_msgs.msg import Twist

rclpy.init()
node = Node("graph_watcher")
node.create_publisher(Twist, "/cmd_vel", 10)


def look():
    now = node.get_clock().now().nanoseconds / 1e9
    names = node.get_node_names_and_namespaces()
    print(f"{now:.2f} nodes {names}", flush=True)
    print(f"{now:.2f} counts chatter pub {node.count_publishers('/chatter')} cmd_vel sub "
          f"{node.count_subscribers('/cmd_vel')} switch {node.count_services('/graph_switch')}", flush=True)
    if ("graph_talker", "/team") in names:
        print(f"{now:.2f} talker pub {node.get_publisher_names_and_types_by_node('graph_talker', '/team')}", flush=True)
        print(f"{now:.2f} talker sub {node.get_subscriber_names_and_types_by_node('graph_talker', '/team')}",
              flush=True)
        services = dict(node.get_service_names_and_types())
        print(f"{now:.2f} switch {services.get('/graph_switch')} talker params "
              f"{sorted(s for s in services if s.startswith('/team/graph_talker/'))}", flush=True)
        print(f"{now:.2f} chatter {dict(node.get_topic_names_and_types()).get('/chatter')}", flush=True)
        print(f"{now:.2f} actions {get_action_names_and_types(node)} served by talker "
              f"{get_action_server_names_and_types_by_node(node, 'graph_talker', '/team')}", flush=True)
    try:
        node.get_publisher_names_and_types_by_node("nobody", "/")
    except Exception as exc:
        print(f"{now:.2f} nobody {type(exc).__name__} {exc}", flush=True)


node.create_timer(0.25, look)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
