#!/usr/bin/env python3
"""Probe 28 (issue 9 item 8): subscribers on one topic in one node share one connection, so they share one type: a
second subscriber declared with another type receives the first one's messages."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry

seen = {"first": set(), "second": set()}
rospy.init_node("p28_subscriber_types")
first = rospy.Subscriber("/odom", Odometry, lambda m: seen["first"].add(type(m).__name__))
second = rospy.Subscriber("/odom", PoseStamped, lambda m: seen["second"].add(type(m).__name__))
rospy.sleep(1.0)
print("first subscriber got", sorted(seen["first"]))
print("second subscriber (declared PoseStamped) got", sorted(seen["second"]))
print("declared types", first.data_class.__name__, second.data_class.__name__, first.type, second.type)
print("connections", first.get_num_connections(), second.get_num_connections())
