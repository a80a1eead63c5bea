#!/usr/bin/env python3
"""Probe 24: turtlesim's parameters through its parameter services, as `ros2 param set/describe` use them: the
background channels' range (0..255) and type, their descriptions, and holonomic turning linear.y on.

Refusal reasons are not printed: rclcpp words them, and the real side here is a model on rclpy, which words them
differently; the accept/refuse outcome is compared.
"""
import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import DescribeParameters, GetParameters, SetParameters
from rclpy.node import Node
from std_srvs.srv import Empty
from turtlesim.msg import Pose


class Probe(Node):
    def __init__(self):
        super().__init__("p24_turtle_parameters")
        self.pose = None
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, msg):
        self.pose = msg

    def wait(self, seconds):
        end = self.get_clock().now().nanoseconds + seconds * 1e9
        while self.get_clock().now().nanoseconds < end:
            rclpy.spin_once(self, timeout_sec=0.05)

    def call(self, kind, service, request):
        client = self.create_client(kind, service)
        if not client.wait_for_service(timeout_sec=5.0):
            return "no service"
        future = client.call_async(request)
        rclpy.spin_until_future_complete(self, future, timeout_sec=2.0)
        self.destroy_client(client)
        return future.result() if future.done() else "no reply within 2 s"

    def set(self, name, value):
        if isinstance(value, bool):
            v = ParameterValue(type=ParameterType.PARAMETER_BOOL, bool_value=value)
        elif isinstance(value, int):
            v = ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=value)
        else:
            v = ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=value)
        reply = self.call(SetParameters, "/turtlesim/set_parameters",
                          SetParameters.Request(parameters=[Parameter(name=name, value=v)]))
        return [r.successful for r in reply.results]

    def get(self, *names):
        reply = self.call(GetParameters, "/turtlesim/get_parameters", GetParameters.Request(names=list(names)))
        return [(v.type, v.integer_value, v.bool_value) for v in reply.values]

    def drive_sideways(self):
        start = self.pose
        for _ in range(5):
            msg = Twist()
            msg.linear.y = 1.0
            self.pub.publish(msg)
            self.wait(0.1)
        self.wait(1.3)  # the 1 s command timeout stops it
        moved = self.pose.y - start.y
        return "moved sideways %s, x kept %s" % ("1.3..1.5 m" if 1.3 < moved < 1.5 else "%.2f m" % moved,
                                                  abs(self.pose.x - start.x) < 1e-4)


rclpy.init()
node = Probe()
while node.pose is None or node.get_clock().now().nanoseconds == 0:
    rclpy.spin_once(node, timeout_sec=0.1)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
print("reset ->", node.call(Empty, "/reset", Empty.Request()))
print("defaults", node.get("background_r", "background_g", "background_b", "holonomic"))
for name, value in (("background_r", 300), ("background_r", -1), ("background_r", 255), ("background_g", 0),
                    ("background_b", 1.5), ("holonomic", 1)):
    print("set", name, value, "->", node.set(name, value))
print("now", node.get("background_r", "background_g", "background_b"))
described = node.call(DescribeParameters, "/turtlesim/describe_parameters",
                      DescribeParameters.Request(names=["background_r", "holonomic"]))
for d in described.descriptors:
    print("describe", d.name, d.type, repr(d.description), d.read_only,
          [(r.from_value, r.to_value, r.step) for r in d.integer_range])
print("holonomic off:", node.drive_sideways())
print("set holonomic True ->", node.set("holonomic", True))
print("holonomic on:", node.drive_sideways())
print("set holonomic False ->", node.set("holonomic", False))
print("set background_r 69 ->", node.set("background_r", 69), node.set("background_g", 86))
print("end")
