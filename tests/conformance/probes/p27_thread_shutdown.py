#!/usr/bin/env python3
"""Probe 27 (issue 9 item 3): a student thread loops until shutdown while the main thread spins; Ctrl+C stops it:
the on_shutdown hook runs while the thread is still alive, then the thread's rate.sleep() raises."""
import threading

import rospy
from geometry_msgs.msg import Twist

rospy.init_node("p27_thread_shutdown")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rospy.sleep(0.5)
T0 = rospy.get_time()
print("#REF %.6f" % T0)


def loop():
    rate = rospy.Rate(10)
    i = 0
    try:
        while not rospy.is_shutdown():
            cmd = Twist()
            cmd.linear.x = 0.1
            cmd.linear.z = i
            pub.publish(cmd)
            print("thread", i, "t=%.3f" % (rospy.get_time() - T0))
            i += 1
            rate.sleep()
    except rospy.ROSInterruptException as e:
        print("thread caught", type(e).__name__, e)
    print("thread ended; is_shutdown", rospy.is_shutdown())


def stop():
    print("on_shutdown hook; thread alive", worker.is_alive())
    pub.publish(Twist())


rospy.on_shutdown(stop)
worker = threading.Thread(target=loop)
worker.start()
# (no print right after spin: real rospy.spin() notices shutdown only every 0.5 s of wall time)
rospy.spin()
worker.join()
print("main done")
