#!/usr/bin/env python3
"""Reference for odom_subscriber (seed 000, Ex. 2): print the robot's pose (x, y, yaw) from /odom."""

import rospy
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion


class OdomSubscriber():

    def __init__(self):
        node_name = "odom_subscriber"
        rospy.init_node(node_name, anonymous=True)
        self.sub = rospy.Subscriber("odom", Odometry, self.callback)
        self.counter = 0
        rospy.loginfo(f"The '{node_name}' node is active...")

    def callback(self, topic_message):
        pose = topic_message.pose.pose
        (roll, pitch, yaw) = euler_from_quaternion(
            [pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w], 'sxyz')
        # /odom arrives about 30 times a second: print every 10th message so the output stays readable.
        if self.counter % 10 == 0:
            print(f"(x,y,θz) = ({pose.position.x:.3f}, {pose.position.y:.3f}, {yaw:.3f})")
        self.counter += 1

    def main(self):
        rospy.spin()


if __name__ == '__main__':
    node = OdomSubscriber()
    node.main()
