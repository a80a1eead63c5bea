#!/usr/bin/env python3
"""Probe 32 (issue 28 item 8): rospy receives on one connection per publisher, each with its own thread and queue;
a connection keeps the queue size it was made with, and its callbacks are the ones registered when it read."""
import threading
import time

import rospy
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Odometry
from tf2_msgs.msg import TFMessage

rospy.init_node("p32_connection_queues")
rospy.sleep(0.01)

# Part 1: /tf from the world and from this node, into one slow subscriber with queue_size=1.
tf_pub = rospy.Publisher("/tf", TFMessage, queue_size=10)
rospy.sleep(0.5)
calls = {}
active = []
overlapped = []


def slow_tf(msg):
    callerid = msg._connection_header["callerid"]
    calls[callerid] = calls.get(callerid, 0) + 1
    active.append(callerid)
    overlapped.append(len(set(active)) > 1)
    time.sleep(0.3)
    active.remove(callerid)


T0 = rospy.get_time()
print("#REF %.6f" % T0)
tf_sub = rospy.Subscriber("/tf", TFMessage, slow_tf, queue_size=1)
rate = rospy.Rate(10)
while rospy.get_time() - T0 < 2.0:
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = "p32_a", "p32_b"
    t.transform.rotation.w = 1.0
    tf_pub.publish(TFMessage([t]))
    rate.sleep()
print("callbacks in 2 s per publisher", sorted(calls.items()))
print("the two publishers' callbacks ran at the same time", any(overlapped))
tf_sub.unregister()

# Part 2: a slow subscriber with queue_size=10, joined 0.5 s later by a fast one with queue_size=1.
slow_seqs = []
fast_seqs = []


def slow_odom(msg):
    slow_seqs.append(msg.header.seq)
    time.sleep(0.25)


rospy.Subscriber("/odom", Odometry, slow_odom, queue_size=10)
rospy.sleep(0.5)
rospy.Subscriber("/odom", Odometry, lambda m: fast_seqs.append((m.header.seq, threading.current_thread().name)),
                 queue_size=1)
rospy.sleep(2.5)
backlog = slow_seqs[1:]
run = 1
while run < len(backlog) and backlog[run] == backlog[0] + run:
    run += 1
print("slow subscriber read its backlog whole (queue_size 10 kept)", 6 <= run <= 9)
print("fast subscriber called only from the next read on", bool(fast_seqs) and fast_seqs[0][0] > backlog[run - 1])
print("fast subscriber called for messages the slow one got", all(s in slow_seqs for s, _ in fast_seqs))
print("threads", sorted({name for _, name in fast_seqs}))
