#!/usr/bin/env python3
"""Reference for move_square (seed 000, Ex. 5 + advanced): a 1 m square from odometry, stopping after two loops."""

import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion

SIDE = 1.0  # m
LOOPS = 2
FORWARD = 0.2  # m/s
TURN = 0.4  # rad/s


def angle_diff(a, b):
    """a - b wrapped to [-pi, pi], so headings either side of +-180 degrees compare correctly."""
    return math.atan2(math.sin(a - b), math.cos(a - b))


class Square():

    def __init__(self):
        self.node_name = "move_square"
        rospy.init_node(self.node_name, anonymous=True)
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        self.sub = rospy.Subscriber("odom", Odometry, self.callback_odom)
        self.rate = rospy.Rate(30)  # Hz: as fast as /odom, so we stop close to the target

        self.x = self.y = self.theta = None
        self.ctrl_c = False
        rospy.on_shutdown(self.shutdownhook)
        rospy.loginfo(f"The '{self.node_name}' node is active...")

    def callback_odom(self, msg):
        pose = msg.pose.pose
        (_, _, yaw) = euler_from_quaternion(
            [pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w], 'sxyz')
        self.x, self.y, self.theta = pose.position.x, pose.position.y, yaw

    def shutdownhook(self):
        self.stop()
        self.ctrl_c = True

    def stop(self):
        self.pub.publish(Twist())

    def drive(self, linear, angular):
        vel = Twist()
        vel.linear.x = linear
        vel.angular.z = angular
        self.pub.publish(vel)

    def forward(self, distance):
        x0, y0 = self.x, self.y
        while not self.ctrl_c:
            remaining = distance - math.hypot(self.x - x0, self.y - y0)
            if remaining <= 0.002:
                break
            self.drive(min(FORWARD, max(0.03, remaining)), 0.0)  # slow down near the end of the side
            self.rate.sleep()
        self.stop()

    def turn(self, angle):
        target = self.theta + angle
        while not self.ctrl_c:
            remaining = angle_diff(target, self.theta)
            if abs(remaining) <= math.radians(0.5):
                break
            self.drive(0.0, math.copysign(min(TURN, max(0.05, abs(remaining))), remaining))
            self.rate.sleep()
        self.stop()

    def main(self):
        while self.x is None and not self.ctrl_c:  # wait for the first odometry message
            self.rate.sleep()
        for _ in range(4 * LOOPS):
            if self.ctrl_c:
                return
            self.forward(SIDE)
            self.turn(math.pi / 2)
        rospy.loginfo("Two loops done: stopping.")
        self.stop()


if __name__ == '__main__':
    node = Square()
    try:
        node.main()
    except rospy.ROSInterruptException:
        pass
