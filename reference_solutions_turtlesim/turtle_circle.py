#!/usr/bin/env python3
"""turtlesim: drive turtle1 in a circle of radius v/ω until Ctrl+C, publishing the command at 10 Hz (turtlesim stops a
turtle whose last command is older than 1 s)."""
import rospy
from geometry_msgs.msg import Twist

LINEAR = 2.0  # m/s
ANGULAR = 1.8  # rad/s: a circle of radius 2.0 / 1.8 = 1.11 m


def main():
    rospy.init_node("turtle_circle")
    pub = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=10)
    cmd = Twist()
    cmd.linear.x = LINEAR
    cmd.angular.z = ANGULAR
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(cmd)
        rate.sleep()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
