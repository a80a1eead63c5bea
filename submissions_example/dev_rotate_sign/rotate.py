#!/usr/bin/env python3
# Rotating left and right (turtlesim). Flaw: clockwise is given a positive angular.z (which turns left).
import math

import rospy
from geometry_msgs.msg import Twist


def rotate():
    rospy.init_node('robot_cleaner', anonymous=True)
    velocity_publisher = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
    vel_msg = Twist()

    speed = float(input("Input your speed (degrees/sec):"))
    angle = float(input("Type your distance (degrees):"))
    clockwise = input("Clockwise?: ") == "1"

    angular_speed = speed * 2 * math.pi / 360
    relative_angle = angle * 2 * math.pi / 360

    if clockwise:
        vel_msg.angular.z = abs(angular_speed)
    else:
        vel_msg.angular.z = -abs(angular_speed)

    rate = rospy.Rate(100)
    while velocity_publisher.get_num_connections() == 0:
        rate.sleep()

    t0 = rospy.Time.now().to_sec()
    current_angle = 0
    while current_angle < relative_angle:
        velocity_publisher.publish(vel_msg)
        rate.sleep()
        t1 = rospy.Time.now().to_sec()
        current_angle = angular_speed * (t1 - t0)

    vel_msg.angular.z = 0
    velocity_publisher.publish(vel_msg)


if __name__ == '__main__':
    try:
        rotate()
    except rospy.ROSInterruptException:
        pass
