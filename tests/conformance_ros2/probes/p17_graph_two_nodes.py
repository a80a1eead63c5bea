#!/usr/bin/env python3
"""Probe 17: the graph as two nodes of one process see it beside the robot: node names, another node's publishers,
services and clients by node, counts across nodes (the robot's /cmd_vel subscription and /odom publisher), and the
error for a node that does not exist.

The robot's own node names differ (rosgrade's world, the real suite's stand-in robot), and so may discovery's timing:
the probe waits for the robot's /odom publisher and prints facts, not the robot's names or counts."""
import time

import rclpy
from geometry_msgs.msg import Twist
from rclpy.action import ActionServer
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import SetBool

try:
    from example_interfaces.action import Fibonacci
except ImportError:
    from test_msgs.action import Fibonacci

# Jazzy's nodes also serve get_type_description (type_description_interfaces), which rosgrade does not: not printed.
PARAMETER_SERVICES = (("describe_parameters", "DescribeParameters"), ("get_parameter_types", "GetParameterTypes"),
                      ("get_parameters", "GetParameters"), ("list_parameters", "ListParameters"),
                      ("set_parameters", "SetParameters"), ("set_parameters_atomically", "SetParametersAtomically"))

rclpy.init()
node = Node("p17_graph")
other = Node("p17_other", namespace="/team")
node.create_publisher(Twist, "/cmd_vel", 10)
node.create_client(SetBool, "/team/p17_switch")
other.create_publisher(String, "p17_chatter", 10)
other.create_subscription(String, "/p17_heard", lambda msg: None, 10)
other.create_service(SetBool, "p17_switch", lambda request, response: response)
ActionServer(other, Fibonacci, "p17_count", lambda goal_handle: Fibonacci.Result())
executor = SingleThreadedExecutor()
executor.add_node(node)
executor.add_node(other)
deadline = time.monotonic() + 15.0
while (node.count_publishers("/odom") < 1 or node.count_subscribers("/cmd_vel") < 1 or len(node.get_node_names()) < 3) \
        and time.monotonic() < deadline:
    executor.spin_once(timeout_sec=0.05)
names = node.get_node_names_and_namespaces()
print("own nodes listed", ("p17_graph", "/") in names, ("p17_other", "/team") in names)
print("fully qualified", "/team/p17_other" in node.get_fully_qualified_node_names(),
      "p17_other" in node.get_node_names())
print("a robot node beside them", any(name not in ("p17_graph", "p17_other") for name, _ in names))
print("robot seen: /odom publishers >= 1", node.count_publishers("/odom") >= 1,
      "/cmd_vel subscribers >= 1", node.count_subscribers("/cmd_vel") >= 1)
# an action server's topics and services are its node's (Fibonacci's package differs: only names printed for them)
publishers = other.get_publisher_names_and_types_by_node("p17_other", "/team")
print("other's action topics", [name for name, _ in publishers if "/_action/" in name])
print("other's action services", [name for name, _ in other.get_service_names_and_types_by_node("p17_other", "/team")
                                   if "/_action/" in name])
print("other's publishers", [pair for pair in publishers if "/_action/" not in pair[0]])
seen = node.get_publisher_names_and_types_by_node("p17_other", "/team")
print("other's publishers seen by node", [pair for pair in seen if "/_action/" not in pair[0]])
print("other's subscribers", node.get_subscriber_names_and_types_by_node("p17_other", "/team"))
services = node.get_service_names_and_types_by_node("p17_other", "/team")
print("other's services", [s for s in services if not s[0].startswith("/team/p17_other/") and "/_action/" not in s[0]])
print("other's parameter services", all(("/team/p17_other/" + name, ["rcl_interfaces/srv/" + kind]) in services
                                        for name, kind in PARAMETER_SERVICES))
print("node's clients", node.get_client_names_and_types_by_node("p17_graph", "/"))
print("switch in all services", dict(node.get_service_names_and_types()).get("/team/p17_switch"))
print("chatter in topics", dict(node.get_topic_names_and_types()).get("/team/p17_chatter"))
print("counts chatter", node.count_publishers("/team/p17_chatter"), node.count_subscribers("/team/p17_chatter"),
      "heard", node.count_subscribers("/p17_heard"), "switch", node.count_services("/team/p17_switch"),
      node.count_clients("/team/p17_switch"), "rosout >=2", node.count_publishers("/rosout") >= 2)
for query in (node.get_publisher_names_and_types_by_node, node.get_service_names_and_types_by_node):
    try:
        query("nobody", "/")
    except Exception as exc:  # noqa: BLE001 - the probe prints what real rclpy raises
        print("unknown node !!", type(exc).__name__, exc)
print("end")
rclpy.shutdown()
