#!/usr/bin/env python3
# Go to goal (turtlesim). Flaw: open loop from the default spawn: it assumes the turtle starts at (5.544, 5.544)
# facing east, turns towards the goal and drives the distance by time, never reading turtle1/pose.
import math

import rospy
from geometry_msgs.msg import Twist

START_X = 5.544445
START_Y = 5.544445


def publish_for(pub, vel, seconds):
    rate = rospy.Rate(50)
    t0 = rospy.Time.now().to_sec()
    while rospy.Time.now().to_sec() - t0 < seconds:
        pub.publish(vel)
        rate.sleep()
    pub.publish(Twist())


if __name__ == '__main__':
    rospy.init_node('go_to_goal')
    x = float(input("x: "))
    y = float(input("y: "))
    pub = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
    rospy.sleep(1.0)

    angle = math.atan2(y - START_Y, x - START_X)
    distance = math.hypot(x - START_X, y - START_Y)
    turn = Twist()
    turn.angular.z = 1.0 if angle > 0 else -1.0
    publish_for(pub, turn, abs(angle))
    drive = Twist()
    drive.linear.x = 1.0
    publish_for(pub, drive, distance)
