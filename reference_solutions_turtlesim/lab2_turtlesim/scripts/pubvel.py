#!/usr/bin/env python3
"""agitr chapter 3's pubvel in Python: random velocities for turtle1 at 2 Hz (forward speed in [0, 1] m/s, turn rate
in [-1, 1] rad/s)."""
import random

import rospy
from geometry_msgs.msg import Twist


def main():
    rospy.init_node("publish_velocity")
    pub = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=1000)
    rate = rospy.Rate(2)
    while not rospy.is_shutdown():
        msg = Twist()
        msg.linear.x = random.random()
        msg.angular.z = 2 * random.random() - 1
        pub.publish(msg)
        rospy.loginfo("Sending random velocity command: linear=%f angular=%f", msg.linear.x, msg.angular.z)
        rate.sleep()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
