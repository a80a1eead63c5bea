#!/usr/bin/env python3
"""Probe 22 (issue 9 item 3): a student thread runs a 10 Hz control loop while the main thread spins or sleeps.

Variants: 'spin_rate' (thread: Rate.sleep, main: rospy.spin), 'sleep_rospy' (thread: rospy.sleep, main: a
rospy.sleep(1.0) loop), 'spin_time' (thread: time.sleep, main: rospy.spin).
"""
import sys
import threading
import time

import rospy
from geometry_msgs.msg import Twist

mode = sys.argv[1]
rospy.init_node("p22_thread")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rospy.sleep(0.5)
T0 = rospy.get_time()
print("#REF %.6f" % T0)


def loop():
    rate = rospy.Rate(10)
    for i in range(12):
        cmd = Twist()
        cmd.linear.x = 0.1
        cmd.linear.z = i
        pub.publish(cmd)
        print("thread", i, "t=%.3f" % (rospy.get_time() - T0))
        if mode == "spin_time":
            time.sleep(0.1)
        elif mode == "sleep_rospy":
            rospy.sleep(0.1)
        else:
            rate.sleep()
    pub.publish(Twist())
    print("thread done", threading.current_thread().name != "MainThread")


worker = threading.Thread(target=loop)
worker.start()
if mode == "sleep_rospy":
    try:
        while not rospy.is_shutdown():
            rospy.sleep(1.0)
            print("main woke t=%.3f" % (rospy.get_time() - T0))
    except rospy.ROSInterruptException:
        pass
else:
    rospy.spin()
worker.join()
print("main done")
