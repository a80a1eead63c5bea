#!/usr/bin/env python3
# A simple ROS subscriber node in Python

import rospy
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion


class Subscriber():

    def callback(self, topic_message):
        pose = topic_message.pose.pose
        orientation = pose.orientation
        (roll, pitch, yaw) = euler_from_quaternion([orientation.x,
                             orientation.y, orientation.z, orientation.w],
                             'sxyz')
        if self.counter > 10:
            self.counter = 0
            rospy.loginfo(f"x = {pose.position.x:.2f} [m], y = {pose.position.y:.2f} [m], yaw = {yaw:.2f} [radians]")
        else:
            self.counter += 1

    def __init__(self):
        node_name = "simple_subscriber"
        topic_name = "odom"
        rospy.init_node(node_name, anonymous=True)
        self.sub = rospy.Subscriber(topic_name, Odometry, self.callback)
        rospy.loginfo(f"The '{node_name}' node is active...")
        self.counter = 0

    def main_loop(self):
        rospy.spin()


if __name__ == '__main__':
    subscriber_instance = Subscriber()
    subscriber_instance.main_loop()
