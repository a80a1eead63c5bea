#!/usr/bin/env python3

import rospy
from geometry_msgs.msg import Twist


class Circle():

    def __init__(self):
        self.node_name = "circle_mover"

        self.pub = rospy.Publisher('/cmd_vel', Twist, queue_size=10)
        rospy.init_node(self.node_name, anonymous=True)
        self.rate = rospy.Rate(10)

        self.ctrl_c = False
        rospy.on_shutdown(self.shutdownhook())

        rospy.loginfo(f"The '{self.node_name}' node is active...")

    def shutdownhook(self):
        print("Stopping the robot...")
        self.pub.publish(Twist())
        self.ctrl_c = True

    def main(self):
        vel_cmd = Twist()
        path_rad = 0.5
        lin_vel = 0.15
        vel_cmd.linear.x = lin_vel
        vel_cmd.angular.z = lin_vel / path_rad
        while not self.ctrl_c:
            self.pub.publish(vel_cmd)
            self.rate.sleep()


if __name__ == '__main__':
    node = Circle()
    try:
        node.main()
    except rospy.ROSInterruptException:
        pass
