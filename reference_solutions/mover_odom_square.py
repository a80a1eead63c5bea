#!/usr/bin/env python3
"""Reference for mover_odom_square (seed 001, Task 5b): a 1 m square from odometry, pausing at each corner.

The course calls this script mover.py; the rubric looks for mover_odom_square.py, then mover.py.
"""

import math

import rospy
import tf
from geometry_msgs.msg import Pose2D, Twist
from nav_msgs.msg import Odometry

EDGE = 1.0  # m
PAUSE = 1.0  # s


class Mover:

    def __init__(self):
        rospy.init_node('mover', anonymous=True)
        self.pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        rospy.Subscriber("odom", Odometry, self.odom_callback)
        rospy.on_shutdown(self.stop)
        self.rate = rospy.Rate(30)
        self.pose = Pose2D()
        self.have_pose = False

    def odom_callback(self, msg):
        # Get (x, y, theta) specification from odometry topic
        quaternion = [msg.pose.pose.orientation.x, msg.pose.pose.orientation.y,
                      msg.pose.pose.orientation.z, msg.pose.pose.orientation.w]
        (roll, pitch, yaw) = tf.transformations.euler_from_quaternion(quaternion)
        self.pose.theta = yaw
        self.pose.x = msg.pose.pose.position.x
        self.pose.y = msg.pose.pose.position.y
        self.have_pose = True

    def stop(self):
        self.pub.publish(Twist())

    def publish(self, linear, angular):
        msg = Twist()
        msg.linear.x = linear
        msg.angular.z = angular
        self.pub.publish(msg)

    def edge(self):
        x0, y0 = self.pose.x, self.pose.y
        travelled = 0.0
        while not rospy.is_shutdown() and travelled < EDGE - 0.002:
            travelled = math.hypot(self.pose.x - x0, self.pose.y - y0)
            self.publish(min(0.2, max(0.03, EDGE - travelled)), 0.0)
            self.rate.sleep()
        self.stop()

    def corner(self):
        target = self.pose.theta + math.pi / 2
        while not rospy.is_shutdown():
            # Wrap the remaining angle to [-pi, pi]: yaw jumps from +pi to -pi.
            remaining = math.atan2(math.sin(target - self.pose.theta), math.cos(target - self.pose.theta))
            if abs(remaining) < math.radians(0.5):
                break
            self.publish(0.0, math.copysign(min(0.5, max(0.05, abs(remaining))), remaining))
            self.rate.sleep()
        self.stop()

    def run(self):
        while not self.have_pose and not rospy.is_shutdown():
            self.rate.sleep()
        for _ in range(4):
            self.edge()
            rospy.sleep(PAUSE)
            self.corner()
            rospy.sleep(PAUSE)
        self.stop()
        rospy.loginfo("Square complete")
        rospy.spin()


if __name__ == '__main__':
    try:
        Mover().run()
    except rospy.ROSInterruptException:
        pass
