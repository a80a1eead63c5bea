#!/usr/bin/env python3

import math
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion


class Square():

    def __init__(self):
        rospy.init_node("move_square", anonymous=True)
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        rospy.Subscriber("odom", Odometry, self.odom_cb)
        self.rate = rospy.Rate(10)
        self.x = self.y = self.yaw = None
        self.ctrl_c = False
        rospy.on_shutdown(self.shutdownhook)

    def odom_cb(self, msg):
        o = msg.pose.pose.orientation
        self.yaw = euler_from_quaternion([o.x, o.y, o.z, o.w])[2]
        self.x = msg.pose.pose.position.x
        self.y = msg.pose.pose.position.y

    def shutdownhook(self):
        self.pub.publish(Twist())
        self.ctrl_c = True

    def go(self, lin, ang):
        t = Twist()
        t.linear.x = lin
        t.angular.z = ang
        self.pub.publish(t)

    def main(self):
        while self.yaw is None:
            self.rate.sleep()
        for side in range(8):
            sx, sy = self.x, self.y
            while not self.ctrl_c and math.hypot(self.x - sx, self.y - sy) < 1.0:
                self.go(0.15, 0.0)
                self.rate.sleep()
            target = self.yaw + math.pi / 2
            while not self.ctrl_c and self.yaw < target:
                self.go(0.0, 0.3)
                self.rate.sleep()
            self.go(0.0, 0.0)
        self.go(0.0, 0.0)


if __name__ == '__main__':
    try:
        Square().main()
    except rospy.ROSInterruptException:
        pass
