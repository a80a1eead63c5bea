#!/usr/bin/env python3
"""The ROS wiki's turtlesim "Moving in a Straight Line" node, as students copy it: it reads the start time with
rospy.Time.now() right after creating its publisher, which works on a real turtlesim (wall clock, no /clock)."""
import rospy
from geometry_msgs.msg import Twist


def move():
    rospy.init_node('robot_cleaner', anonymous=True)
    velocity_publisher = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
    vel_msg = Twist()
    speed = float(input("Input your speed:"))
    distance = float(input("Type your distance:"))
    isForward = input("Foward?: ")
    vel_msg.linear.x = abs(speed) if isForward == "1" else -abs(speed)
    print("start time is zero:", rospy.Time.now().to_sec() == 0.0, "wallclock:", rospy.rostime.is_wallclock())
    while not rospy.is_shutdown():
        t0 = rospy.Time.now().to_sec()
        current_distance = 0
        while current_distance < distance:
            velocity_publisher.publish(vel_msg)
            t1 = rospy.Time.now().to_sec()
            current_distance = speed * (t1 - t0)
        vel_msg.linear.x = 0
        velocity_publisher.publish(vel_msg)
        break


if __name__ == '__main__':
    move()
