#!/usr/bin/env python3
"""Reference for figure_of_eight (Sheffield COM2009 Assignment 2, Task 1 "Velocity Control", in rospy).

Two loops of 1 m diameter, the first anticlockwise and the second clockwise, back at the start after about 60 s.
The turn of each loop is measured from /odom, so the robot closes each loop wherever it started. The node logs its
pose relative to the start pose once a second: odometry need not read zero at the start.
"""

import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion

RADIUS = 0.5  # m: loops of 1 m diameter
SPEED = 0.105  # m/s: two loops (2 pi m) in 60 s
TURN_RATE = SPEED / RADIUS  # rad/s


def angle_diff(a, b):
    """a - b wrapped to [-pi, pi]."""
    return math.atan2(math.sin(a - b), math.cos(a - b))


class FigureEight():

    def __init__(self):
        rospy.init_node("figure_eight", anonymous=True)
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        self.sub = rospy.Subscriber("odom", Odometry, self.callback_odom)
        self.rate = rospy.Rate(30)  # Hz: as fast as /odom
        self.pose = None  # latest (x, y, yaw) from /odom
        self.start = None  # the pose when the node started
        self.ctrl_c = False
        rospy.on_shutdown(self.shutdownhook)
        rospy.Timer(rospy.Duration(1.0), self.log_pose)

    def callback_odom(self, msg):
        p = msg.pose.pose
        (_, _, yaw) = euler_from_quaternion([p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w])
        self.pose = (p.position.x, p.position.y, yaw)
        if self.start is None:
            self.start = self.pose

    def relative_pose(self):
        """The pose in the start frame: x ahead of the start, y to its left, yaw from the start heading."""
        (x, y, yaw), (x0, y0, yaw0) = self.pose, self.start
        dx, dy = x - x0, y - y0
        return (math.cos(yaw0) * dx + math.sin(yaw0) * dy, -math.sin(yaw0) * dx + math.cos(yaw0) * dy,
                angle_diff(yaw, yaw0))

    def log_pose(self, event):
        if self.start is None:
            return
        x, y, yaw = self.relative_pose()
        rospy.loginfo(f"x={x:.2f} [m], y={y:.2f} [m], yaw={math.degrees(yaw):.1f} [degrees].")

    def shutdownhook(self):
        self.ctrl_c = True
        self.pub.publish(Twist())

    def loop(self, direction):
        """Drive one full circle, anticlockwise (+1) or clockwise (-1), until the heading has turned 360 degrees."""
        turned, last = 0.0, self.pose[2]
        vel = Twist()
        while not self.ctrl_c:
            turned += angle_diff(self.pose[2], last)
            last = self.pose[2]
            remaining = 2 * math.pi - abs(turned)
            if remaining <= 0.005:
                break
            scale = min(1.0, max(0.2, remaining / 0.2))  # ease into the end of the loop
            vel.linear.x, vel.angular.z = SPEED * scale, direction * TURN_RATE * scale
            self.pub.publish(vel)
            self.rate.sleep()

    def main(self):
        while self.start is None and not self.ctrl_c:
            self.rate.sleep()
        for direction in (1, -1):
            if not self.ctrl_c:
                self.loop(direction)
        self.pub.publish(Twist())
        while not self.ctrl_c:  # keep logging until the node is shut down
            self.rate.sleep()


if __name__ == '__main__':
    try:
        FigureEight().main()
    except rospy.ROSInterruptException:
        pass
