#!/usr/bin/env python3
"""turtlesim: rotate turtle1 by an angle at a speed, both typed in degrees, clockwise or not (wiki "Rotating Left and
Right"), then stop it with a zero Twist."""
import math

import rospy
from geometry_msgs.msg import Twist


def rotate():
    rospy.init_node("robot_cleaner", anonymous=True)
    velocity_publisher = rospy.Publisher("/turtle1/cmd_vel", Twist, queue_size=10)
    vel_msg = Twist()

    print("Let's rotate your robot")
    speed = float(input("Input your speed (degrees/sec): "))
    angle = float(input("Type your distance (degrees): "))
    clockwise = input("Clockwise? (1/0): ").strip() in ("1", "y", "yes", "True", "true")

    angular_speed = math.radians(abs(speed))
    relative_angle = math.radians(angle)
    vel_msg.angular.z = -angular_speed if clockwise else angular_speed

    rate = rospy.Rate(100)
    while velocity_publisher.get_num_connections() == 0 and not rospy.is_shutdown():
        rate.sleep()  # turtlesim has not connected yet: a message published now would be lost
    t0 = rospy.Time.now().to_sec()
    current_angle = 0.0
    while current_angle < relative_angle and not rospy.is_shutdown():
        velocity_publisher.publish(vel_msg)
        rate.sleep()
        t1 = rospy.Time.now().to_sec()
        current_angle = angular_speed * (t1 - t0)
    vel_msg.angular.z = 0.0
    velocity_publisher.publish(vel_msg)


if __name__ == "__main__":
    try:
        rotate()
    except rospy.ROSInterruptException:
        pass
