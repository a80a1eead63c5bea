#!/usr/bin/env python3

import rospy
from geometry_msgs.msg import Twist


class Circle():

    def __init__(self):
        self.node_name = "move_circle"
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        rospy.init_node(self.node_name, anonymous=True)
        self.rate = rospy.Rate(10)
        self.ctrl_c = False
        rospy.on_shutdown(self.shutdownhook)
        rospy.loginfo(f"The '{self.node_name}' node is active...")

    def shutdownhook(self):
        self.pub.publish(Twist())
        self.ctrl_c = True

    def main(self):
        msg = Twist()
        # faster is better! radius = v / w = 0.5
        msg.linear.x = 0.5
        msg.angular.z = 1.0
        while not self.ctrl_c:
            self.pub.publish(msg)
            self.rate.sleep()


if __name__ == '__main__':
    node = Circle()
    try:
        node.main()
    except rospy.ROSInterruptException:
        pass
