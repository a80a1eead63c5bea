#!/usr/bin/env python3
# Drive to the corners of the square one after the other, then do it again.

import math
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion

CORNERS = [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)]  # the robot starts at (0, 0)


class Square:

    def __init__(self):
        rospy.init_node("move_square")
        self.pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
        rospy.Subscriber("/odom", Odometry, self.odom_callback)
        rospy.on_shutdown(self.stop)
        self.rate = rospy.Rate(20)
        self.x = self.y = self.yaw = 0.0
        self.ready = False

    def odom_callback(self, msg):
        q = msg.pose.pose.orientation
        self.yaw = euler_from_quaternion([q.x, q.y, q.z, q.w])[2]
        self.x, self.y = msg.pose.pose.position.x, msg.pose.pose.position.y
        self.ready = True

    def stop(self):
        self.pub.publish(Twist())

    def drive_to(self, cx, cy):
        best = math.inf
        while not rospy.is_shutdown():
            d = math.hypot(cx - self.x, cy - self.y)
            if d < 0.02 or d > best + 0.001:  # arrived, or started to move away
                break
            best = min(best, d)
            t = Twist()
            t.linear.x = 0.2 if d > 0.2 else 0.05
            self.pub.publish(t)
            self.rate.sleep()
        self.stop()

    def turn_left(self):
        start = self.yaw
        while not rospy.is_shutdown():
            turned = math.atan2(math.sin(self.yaw - start), math.cos(self.yaw - start))
            if turned >= math.pi / 2 - 0.01:
                break
            t = Twist()
            t.angular.z = 0.4 if turned < 1.4 else 0.05
            self.pub.publish(t)
            self.rate.sleep()
        self.stop()

    def main(self):
        while not self.ready:
            self.rate.sleep()
        for loop in range(2):
            for cx, cy in CORNERS:
                self.drive_to(cx, cy)
                self.turn_left()
        self.stop()


if __name__ == "__main__":
    try:
        Square().main()
    except rospy.ROSInterruptException:
        pass
