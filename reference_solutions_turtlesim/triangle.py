#!/usr/bin/env python3
"""turtlesim: draw an equilateral triangle by repeating "forward one side, turn left 120 degrees" three times, stopping
the turtle with a zero Twist after each move and at the end."""
import math

import rospy
from geometry_msgs.msg import Twist

SIDE = 2.0  # m
SPEED = 1.0  # m/s
TURN_SPEED = math.radians(60)  # rad/s


def drive(pub, linear, angular, duration):
    """Publish one command for ``duration`` seconds of ROS time, then a zero Twist."""
    cmd = Twist()
    cmd.linear.x = linear
    cmd.angular.z = angular
    rate = rospy.Rate(100)
    t0 = rospy.Time.now().to_sec()
    while rospy.Time.now().to_sec() - t0 < duration and not rospy.is_shutdown():
        pub.publish(cmd)
        rate.sleep()
    pub.publish(Twist())


def main():
    rospy.init_node("triangle")
    pub = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=10)
    rate = rospy.Rate(100)
    while pub.get_num_connections() == 0 and not rospy.is_shutdown():
        rate.sleep()
    for _ in range(3):
        drive(pub, SPEED, 0.0, SIDE / SPEED)
        drive(pub, 0.0, TURN_SPEED, math.radians(120) / TURN_SPEED)


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
