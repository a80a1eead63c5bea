#!/usr/bin/env python3
# A student thread holds a threading.Lock across a sleep while the main loop and an odometry callback take the same
# lock: real rospy just makes them wait; the lockstep scheduler must not deadlock on it. Then a ThreadPoolExecutor.
import concurrent.futures
import sys
import threading

import rospy
from nav_msgs.msg import Odometry

lock = getattr(threading, sys.argv[1])()  # Lock or RLock
counts = {"thread": 0, "main": 0, "odom": 0}


def on_odom(msg):
    with lock:
        counts["odom"] += 1


def worker():
    for _ in range(5):
        with lock:
            counts["thread"] += 1
            rospy.sleep(0.2)  # holds the lock: the others wait for it
        rospy.sleep(0.05)


rospy.init_node("lock_across_sleep")
rospy.Subscriber("/odom", Odometry, on_odom)
rospy.sleep(0.1)
thread = threading.Thread(target=worker)
thread.start()
rate = rospy.Rate(20)
while thread.is_alive():
    with lock:
        counts["main"] += 1
    rate.sleep()
thread.join()
print("thread", counts["thread"], "main > 5", counts["main"] > 5, "odom > 20", counts["odom"] > 20)
with concurrent.futures.ThreadPoolExecutor(2) as pool:
    print("executor", pool.submit(lambda: (rospy.sleep(0.2), 42)[1]).result())
