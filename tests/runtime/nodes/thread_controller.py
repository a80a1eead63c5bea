#!/usr/bin/env python3
# A student-style node whose control loop runs in its own thread (10 Hz Rate) while the main thread spins; an
# odometry callback and a threading.Event shared between the threads make the interleaving matter.
import threading

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


class Controller:
    def __init__(self):
        rospy.init_node("thread_controller")
        self.x = None
        self.have_odom = threading.Event()
        self.pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
        rospy.Subscriber("/odom", Odometry, self.on_odom)

    def on_odom(self, msg):
        self.x = msg.pose.pose.position.x
        self.have_odom.set()

    def loop(self):
        self.have_odom.wait()
        rate = rospy.Rate(10)
        cmd = Twist()
        while not rospy.is_shutdown() and self.x < 0.5:
            cmd.linear.x = 0.2
            self.pub.publish(cmd)
            rate.sleep()
        self.pub.publish(Twist())
        print("stopped at x=%.3f" % self.x)


node = Controller()
worker = threading.Thread(target=node.loop)
worker.start()
rospy.spin()
