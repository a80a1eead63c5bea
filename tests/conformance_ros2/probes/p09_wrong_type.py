#!/usr/bin/env python3
"""Probe 9: publishing the wrong type, and a second type on /cmd_vel from one node (one DDS participant)."""
import rclpy
from geometry_msgs.msg import Twist, TwistStamped
from rclpy.node import Node
from std_msgs.msg import String


def show(label, fn):
    try:
        value = fn()
        print(label, "->", repr(value))
    except Exception as e:
        print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))


rclpy.init()
node = Node("p09_wrong_type")
pub = node.create_publisher(TwistStamped, "/cmd_vel", 10)
while node.get_clock().now().nanoseconds == 0 or pub.get_subscription_count() == 0:
    rclpy.spin_once(node, timeout_sec=0.01)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
show("publish Twist on a TwistStamped publisher", lambda: pub.publish(Twist()))
show("publish None", lambda: pub.publish(None))
show("publish a dict", lambda: pub.publish({"twist": {}}))
show("publish the class", lambda: pub.publish(TwistStamped))
show("publish a str on a String publisher",
     lambda: node.create_publisher(String, "/chatter", 10).publish("hello"))
show("create_publisher(Twist, '/cmd_vel')", lambda: node.create_publisher(Twist, "/cmd_vel", 10).topic_name)
show("create_subscription(Twist, '/cmd_vel')",
     lambda: node.create_subscription(Twist, "/cmd_vel", lambda m: None, 10).topic_name)
show("create_publisher(Twist, 'cmd_vel') relative", lambda: node.create_publisher(TwistStamped, "cmd_vel", 10).topic_name)
show("create_publisher(Twist, '/bad topic')", lambda: node.create_publisher(Twist, "/bad topic", 10))
show("create_publisher(int, '/x')", lambda: node.create_publisher(int, "/x", 10))
show("create_publisher with qos 'ten'", lambda: node.create_publisher(Twist, "/x", "ten"))
bad = TwistStamped()  # linear.y numbers the publishes, to tell on the robot's side which of them arrived
bad.twist.linear.y = 1.0
bad.twist.linear.x = "fast"
show("publish with linear.x = 'fast'", lambda: pub.publish(bad))
bad.twist.linear.x = 1
bad.twist.linear.y = 2.0
show("publish with linear.x = 1 (int)", lambda: pub.publish(bad))
bad.twist.linear.x = None
bad.twist.linear.y = 3.0
show("publish with linear.x = None", lambda: pub.publish(bad))
bad.twist.linear.x = 0.0
bad.twist.linear.y = 4.0
bad.header.frame_id = 3
show("publish with frame_id = 3", lambda: pub.publish(bad))
bad.header.frame_id = ""
bad.twist = Twist()
bad.twist.linear = 5
show("publish with twist.linear = 5", lambda: pub.publish(bad))
show("pub.topic_name", lambda: pub.topic_name)
good = TwistStamped()
good.twist.linear.y = 5.0
show("publish a good one", lambda: pub.publish(good))
rclpy.spin_once(node, timeout_sec=0.2)
rclpy.shutdown()
print("end")
