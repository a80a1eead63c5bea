#!/usr/bin/env python3
# Triangle by repetition (turtlesim). Flaw: turns 60 degrees, the triangle's inside angle, instead of 120.
import math

import rospy
from geometry_msgs.msg import Twist


def forward(pub, distance, speed=1.0):
    vel = Twist()
    vel.linear.x = speed
    rate = rospy.Rate(50)
    t0 = rospy.Time.now().to_sec()
    while speed * (rospy.Time.now().to_sec() - t0) < distance:
        pub.publish(vel)
        rate.sleep()
    pub.publish(Twist())


def left(pub, degrees, speed_deg=45.0):
    vel = Twist()
    vel.angular.z = math.radians(speed_deg)
    rate = rospy.Rate(50)
    t0 = rospy.Time.now().to_sec()
    while speed_deg * (rospy.Time.now().to_sec() - t0) < degrees:
        pub.publish(vel)
        rate.sleep()
    pub.publish(Twist())


if __name__ == '__main__':
    rospy.init_node('triangle')
    pub = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
    rospy.sleep(1.0)
    for i in range(3):
        forward(pub, 2.0)
        left(pub, 60)  # the angles of an equilateral triangle are 60 degrees
