"""Probe: API behaviours printed one per line (types, errors, parameters, logging filters, spin_once, starvation)."""
import sys
import time
import warnings

import rclpy
from geometry_msgs.msg import Twist, TwistStamped
from rclpy.duration import Duration
from rclpy.exceptions import NotInitializedException, ParameterNotDeclaredException
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile
from std_msgs.msg import String


def attempt(label, fn):
    try:
        print(f"{label}: {fn()!r}")
    except Exception as exc:
        print(f"{label}: {type(exc).__module__}.{type(exc).__name__}: {exc}")


attempt("node before init", lambda: Node("early"))
rclpy.init()
node = Node("api", parameter_overrides=[Parameter("speed", value=2)])
attempt("now before spin", lambda: node.get_clock().now())
attempt("declare int into double", lambda: node.declare_parameter("speed", 0.5))
attempt("declare radius", lambda: node.declare_parameter("radius", 0.5).value)
attempt("use_sim_time", lambda: node.get_parameter("use_sim_time").value)
attempt("undeclared", lambda: node.get_parameter("nope"))
attempt("set wrong type", lambda: node.set_parameters([Parameter("radius", value="x")])[0].successful)
pub = node.create_publisher(TwistStamped, "cmd_vel", 10)
latched = node.create_publisher(String, "status", QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
attempt("publish wrong type", lambda: pub.publish(Twist()))
attempt("bad qos", lambda: node.create_publisher(Twist, "x", "10"))
attempt("bad topic", lambda: node.create_publisher(Twist, "bad topic", 10))
attempt("subscription count", lambda: pub.get_subscription_count())
attempt("fqn", lambda: (node.get_name(), node.get_namespace(), node.get_fully_qualified_name()))
log = node.get_logger()
for i in range(3):
    log.info(f"once {i}", once=True)
    log.info(f"skip {i}", skip_first=True)
log.debug("hidden debug")
with warnings.catch_warnings():
    warnings.simplefilter("always")
    log.warn("old warn")
attempt("log non-str", lambda: log.info(5))
ticks = []
node.create_timer(0.5, lambda: ticks.append(node.get_clock().now().nanoseconds))
for _ in range(4):
    rclpy.spin_once(node, timeout_sec=1.0)
print("ticks", ticks)
start = time.time()
rclpy.spin_once(node, timeout_sec=0)
print("spin_once(0) waited", time.time() - start)
attempt("duration", lambda: (Duration(seconds=1.5) + Duration(nanoseconds=5), Duration(seconds=1) * 0.5))
node.destroy_node()
attempt("publish after destroy", lambda: pub.publish(TwistStamped()))
rclpy.shutdown()
attempt("ok after shutdown", lambda: rclpy.ok())
attempt("shutdown twice", lambda: rclpy.shutdown())
