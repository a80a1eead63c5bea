#!/usr/bin/env python3
# A pure-Python busy wait on a value a callback sets: it must end, at the same sim time on every run.
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


class Mover:
    def __init__(self):
        rospy.init_node("busy_wait")
        self.pose = None
        rospy.Subscriber("/odom", Odometry, self.callback)
        self.pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)

    def callback(self, msg):
        self.pose = msg.pose.pose

    def run(self):
        while self.pose is None:
            pass
        print("first odom x =", self.pose.position.x)
        cmd = Twist()
        cmd.angular.z = 0.5
        rate = rospy.Rate(10)
        for _ in range(20):
            self.pub.publish(cmd)
            rate.sleep()
        self.pub.publish(Twist())


Mover().run()
