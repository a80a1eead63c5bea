#!/usr/bin/env python3
"""Reference for move_circle (seed 000, Ex. 4): a 0.5 m radius circle until Ctrl+C, then a zero Twist."""

import rospy
from geometry_msgs.msg import Twist


class Circle():

    def __init__(self):
        self.node_name = "move_circle"
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        rospy.init_node(self.node_name, anonymous=True)
        self.rate = rospy.Rate(10)  # Hz

        self.ctrl_c = False
        rospy.on_shutdown(self.shutdownhook)

        rospy.loginfo(f"The '{self.node_name}' node is active...")

    def shutdownhook(self):
        # Stop the robot: the base keeps the last command it was given.
        self.pub.publish(Twist())
        self.ctrl_c = True

    def main(self):
        radius = 0.5  # m
        vel = Twist()
        vel.linear.x = 0.1  # m/s, below the 0.26 m/s limit
        vel.angular.z = vel.linear.x / radius  # rad/s: v = r * omega
        while not self.ctrl_c:
            self.pub.publish(vel)
            self.rate.sleep()


if __name__ == '__main__':
    node = Circle()
    try:
        node.main()
    except rospy.ROSInterruptException:
        pass
