#!/usr/bin/env python3
# Triangle by repetition (turtlesim). Flaw: never publishes a zero Twist; each new command replaces the last one and
# the turtle stops at the end only because turtlesim drops a command after 1 s.
import math

import rospy
from geometry_msgs.msg import Twist


def send(pub, linear, angular, seconds):
    vel = Twist()
    vel.linear.x = linear
    vel.angular.z = angular
    rate = rospy.Rate(100)
    end = rospy.Time.now() + rospy.Duration(seconds)
    while rospy.Time.now() < end:
        pub.publish(vel)
        rate.sleep()


if __name__ == '__main__':
    rospy.init_node('triangle')
    pub = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
    rospy.sleep(1.0)
    for side in range(3):
        send(pub, 1.5, 0.0, 2.0)                      # a 3 m side
        send(pub, 0.0, math.radians(90), 120 / 90.0)  # 120 degrees at 90 degrees/s
