#!/usr/bin/env python3
"""Probe 22: turtlesim's services as a student calls them: spawn (a free name, a taken one), kill (unknown, known),
set_pen off, teleport_absolute and teleport_relative (the pose after), reset; the replies, and what turtlesim logs.
"""
import rclpy
from rcl_interfaces.msg import Log
from rclpy.node import Node
from std_srvs.srv import Empty
from turtlesim.msg import Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative


class Probe(Node):
    def __init__(self):
        super().__init__("p22_turtle_services")
        self.pose = None
        self.logs = []
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.create_subscription(Log, "/rosout", self.on_log, 100)

    def on_pose(self, msg):
        self.pose = msg

    def on_log(self, msg):
        if msg.name == "turtlesim":
            self.logs.append(f"{msg.level} {msg.msg}")

    def wait(self, seconds):
        end = self.get_clock().now().nanoseconds + seconds * 1e9
        while self.get_clock().now().nanoseconds < end:
            rclpy.spin_once(self, timeout_sec=0.05)

    def call(self, kind, service, **fields):
        client = self.create_client(kind, service)
        if not client.wait_for_service(timeout_sec=5.0):
            return "no service"
        future = client.call_async(kind.Request(**fields))
        rclpy.spin_until_future_complete(self, future, timeout_sec=2.0)
        self.destroy_client(client)
        return future.result() if future.done() else "no reply within 2 s"

    def show_pose(self, label):
        self.wait(0.2)
        p = self.pose
        print(label, "x %.4f y %.4f theta %.4f" % (p.x, p.y, p.theta))


rclpy.init()
node = Probe()
while node.pose is None or node.get_clock().now().nanoseconds == 0:
    rclpy.spin_once(node, timeout_sec=0.1)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
print("reset first ->", node.call(Empty, "/reset"))
print("spawn '' ->", node.call(Spawn, "/spawn", x=1.0, y=2.0, theta=0.5))
print("spawn 'leo' ->", node.call(Spawn, "/spawn", name="leo", x=3.0, y=3.0))
print("spawn 'leo' again ->", node.call(Spawn, "/spawn", name="leo", x=4.0, y=4.0))
print("kill 'nobody' ->", node.call(Kill, "/kill", name="nobody"))
print("kill 'leo' ->", node.call(Kill, "/kill", name="leo"))
print("set_pen off ->", node.call(SetPen, "/turtle1/set_pen", r=255, off=1))
print("teleport_absolute ->", node.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=2.0, y=3.0, theta=1.0))
node.show_pose("after teleport_absolute")
print("teleport_relative ->", node.call(TeleportRelative, "/turtle1/teleport_relative", linear=1.0, angular=0.5))
node.show_pose("after teleport_relative")
print("teleport_absolute off the canvas ->",
      node.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=20.0, y=-3.0, theta=0.0))
node.show_pose("after teleport off the canvas")
print("clear ->", node.call(Empty, "/clear"))
print("reset ->", node.call(Empty, "/reset"))
node.show_pose("after reset")
print("spawn '' after reset ->", node.call(Spawn, "/spawn", x=1.0, y=1.0))
node.wait(0.3)
for line in node.logs:
    print("turtlesim said", line)
print("end")
