#!/usr/bin/env python3
"""Probe 25 (issue 9 item 8): subscribers on one topic share one connection; sys.exit() in a callback."""
import sys
import time

import rospy
from nav_msgs.msg import Odometry
from tf2_msgs.msg import TFMessage

order = []
exits = []


def fast(msg):
    order.append("A")


def slow(msg):
    order.append("B")
    time.sleep(0.2)


def quitter(msg):
    exits.append(1)
    sys.exit("quitting in a callback")


rospy.init_node("p25_shared_subscribers")
a = rospy.Subscriber("/odom", Odometry, fast, queue_size=10)
b = rospy.Subscriber("/odom", Odometry, slow, queue_size=1)
rospy.Subscriber("/tf", TFMessage, quitter)
rospy.sleep(2.0)
n_a, n_b = order.count("A"), order.count("B")
print("callbacks interleave A,B,A,B", all(x != y for x, y in zip(order, order[1:])))
print("fast subscriber paced by the slow one", 6 <= n_a <= 12)
print("both called as often", abs(n_a - n_b) <= 1)
print("sys.exit() callback kept being called", len(exits) > 20)
print("connections", a.get_num_connections(), b.get_num_connections())
