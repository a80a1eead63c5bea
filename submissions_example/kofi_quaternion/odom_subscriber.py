#!/usr/bin/env python3
# A simple ROS subscriber node in Python

import rospy
from nav_msgs.msg import Odometry


class Subscriber():

    def callback(self, topic_message):
        pose = topic_message.pose.pose
        # theta_z is the z part of the orientation
        print(f"(x,y,θz) = ({pose.position.x:.2f}, {pose.position.y:.2f}, {pose.orientation.z:.2f})")

    def __init__(self):
        node_name = "odom_subscriber"
        rospy.init_node(node_name, anonymous=True)
        self.sub = rospy.Subscriber("odom", Odometry, self.callback)
        rospy.loginfo(f"The '{node_name}' node is active...")

    def main_loop(self):
        rospy.spin()


if __name__ == '__main__':
    subscriber_instance = Subscriber()
    subscriber_instance.main_loop()
