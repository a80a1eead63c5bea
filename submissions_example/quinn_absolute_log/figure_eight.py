#!/usr/bin/env python3
# Task 1: figure of eight, closed loop on the heading. Bug: logs the raw /odom pose, not the pose relative to
# where the robot started (odometry does not read zero at the start in the arena).
import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion


class Eight:
    def __init__(self):
        rospy.init_node('figure_eight', anonymous=True)
        self.pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
        rospy.Subscriber('odom', Odometry, self.on_odom)
        self.x = self.y = self.yaw = None
        self.stopping = False
        rospy.on_shutdown(self.on_shutdown)
        rospy.Timer(rospy.Duration(1), self.report)

    def on_odom(self, msg):
        o = msg.pose.pose.orientation
        self.yaw = euler_from_quaternion([o.x, o.y, o.z, o.w])[2]
        self.x, self.y = msg.pose.pose.position.x, msg.pose.pose.position.y

    def report(self, _):
        if self.x is not None:
            rospy.loginfo(f"x={self.x:.2f} [m], y={self.y:.2f} [m], yaw={math.degrees(self.yaw):.1f} [degrees].")

    def on_shutdown(self):
        self.stopping = True
        self.pub.publish(Twist())

    def circle(self, w):
        rate = rospy.Rate(20)
        turned, prev = 0.0, self.yaw
        cmd = Twist()
        cmd.linear.x, cmd.angular.z = 0.1, w
        while not self.stopping and turned < 2 * math.pi:
            d = self.yaw - prev
            turned += abs(math.atan2(math.sin(d), math.cos(d)))
            prev = self.yaw
            self.pub.publish(cmd)
            rate.sleep()

    def run(self):
        while self.yaw is None and not rospy.is_shutdown():
            rospy.sleep(0.05)
        self.circle(0.2)
        self.circle(-0.2)
        self.pub.publish(Twist())
        rospy.spin()


if __name__ == '__main__':
    Eight().run()
