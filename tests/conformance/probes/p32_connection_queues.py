#!/usr/bin/env python3
"""Probe 32 (issue 28 item 8): rospy receives on one connection per publisher, each with its own thread and queue;
a connection keeps the queue size it was made with, each read keeps the last queue_size messages of what arrived
since the last one, and calls the callbacks registered when it read."""
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


slow_sub = rospy.Subscriber("/odom", Odometry, slow_odom, queue_size=10)
rospy.sleep(0.5)
fast_sub = rospy.Subscriber("/odom", Odometry,
                            lambda m: fast_seqs.append((m.header.seq, threading.current_thread().name)), queue_size=1)
rospy.sleep(2.5)
slow_sub.unregister()
fast_sub.unregister()
backlog = slow_seqs[1:]
run = 1
while run < len(backlog) and backlog[run] == backlog[0] + run:
    run += 1
print("slow subscriber read its backlog whole (queue_size 10 kept)", 6 <= run <= 9)
print("fast subscriber called only from the next read on", bool(fast_seqs) and fast_seqs[0][0] > backlog[run - 1])
print("fast subscriber called for messages the slow one got", all(s in slow_seqs for s, _ in fast_seqs))
print("threads", sorted({name for _, name in fast_seqs}))

# Part 3: queue_size=3 under a 0.3 s callback: each read keeps the last 3 of the ~9 messages received meanwhile.
read_seqs = []


def slow_read(msg):
    read_seqs.append(msg.header.seq)
    time.sleep(0.3)


rospy.Subscriber("/odom", Odometry, slow_read, queue_size=3)
rospy.sleep(1.3)
gaps = [b - a for a, b in zip(read_seqs, read_seqs[1:])]
print("queue_size 3: the second read's messages are consecutive", gaps[1:3] == [1, 1])
