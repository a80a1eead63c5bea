#!/usr/bin/env python3
# Moving in a straight line (turtlesim). Flaw: one velocity command, then time.sleep(distance / speed) to time the
# move: turtlesim stops a turtle whose last command is older than 1 s, so it drives about speed x 1 s.
import time

import rospy
from geometry_msgs.msg import Twist


def move():
    rospy.init_node('robot_cleaner', anonymous=True)
    velocity_publisher = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
    vel_msg = Twist()

    print("Let's move your robot")
    speed = float(input("Input your speed:"))
    distance = float(input("Type your distance:"))
    isForward = int(input("Foward?: "))

    if isForward:
        vel_msg.linear.x = abs(speed)
    else:
        vel_msg.linear.x = -abs(speed)

    rate = rospy.Rate(100)
    while velocity_publisher.get_num_connections() == 0:
        rate.sleep()

    velocity_publisher.publish(vel_msg)
    time.sleep(distance / abs(speed))
    vel_msg.linear.x = 0
    velocity_publisher.publish(vel_msg)


if __name__ == '__main__':
    try:
        move()
    except rospy.ROSInterruptException:
        pass
