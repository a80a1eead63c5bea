"""Probe: behaviours the ROS 2 conformance suite pinned down: sleep_for on sim time while another thread spins,
ClockType's text, one type per topic in a context, classes without type support, the warning after a bad node name,
create_timer after shutdown."""
import threading

import rclpy
from geometry_msgs.msg import Twist, TwistStamped
from rclpy.duration import Duration
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Empty


def attempt(label, fn):
    try:
        print(f"{label}: {fn()!r}")
    except Exception as exc:
        print(f"{label}: {type(exc).__module__}.{type(exc).__name__}: {exc}")


rclpy.init()
attempt("bad name", lambda: Node("bad name"))
attempt("bad namespace", lambda: Node("x", namespace="bad ns"))
node = Node("edge")
print("clock type", node.get_clock().clock_type, f"{node.get_clock().clock_type}")
pub = node.create_publisher(TwistStamped, "/cmd_vel", 10)
attempt("second type publisher", lambda: node.create_publisher(Twist, "/cmd_vel", 10))
attempt("second type subscription", lambda: node.create_subscription(Twist, "cmd_vel", print, 10))
attempt("same type again", lambda: node.create_subscription(TwistStamped, "/cmd_vel", print, 10).topic_name)
attempt("String on /rosout", lambda: node.create_publisher(String, "/rosout", 10))
attempt("String on /clock", lambda: node.create_publisher(String, "/clock", 10))
node.destroy_subscription(node._subscriptions[-1])
node.destroy_publisher(pub)
attempt("other type once the topic is free", lambda: node.create_publisher(Twist, "/cmd_vel", 10).topic_name)
attempt("int type", lambda: node.create_publisher(int, "/x", 10))
attempt("service as message", lambda: node.create_subscription(Empty, "/x", print, 10))
attempt("message as service", lambda: node.create_client(String, "/srv"))
while node.get_clock().now().nanoseconds == 0:
    rclpy.spin_once(node, timeout_sec=0.1)
executor = SingleThreadedExecutor()
executor.add_node(node)
spinner = threading.Thread(target=executor.spin)
spinner.start()
before = node.get_clock().now()
slept = node.get_clock().sleep_for(Duration(seconds=0.3))
print("sleep_for", slept, (node.get_clock().now() - before).nanoseconds)
executor.shutdown()
spinner.join()
rclpy.shutdown()
attempt("timer after shutdown", lambda: node.create_timer(0.1, lambda: None))
