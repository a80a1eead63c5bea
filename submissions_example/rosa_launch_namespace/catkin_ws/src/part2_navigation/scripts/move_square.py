#!/usr/bin/env python3

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion
from math import sqrt, pi, atan2, sin, cos


class Square():

    def callback_function(self, topic_data: Odometry):
        pose = topic_data.pose.pose
        position = pose.position
        orientation = pose.orientation
        (roll, pitch, yaw) = euler_from_quaternion([orientation.x, orientation.y, orientation.z, orientation.w], 'sxyz')
        self.x = position.x
        self.y = position.y
        self.theta_z = yaw
        if self.startup:
            self.startup = False
            self.x0 = self.x
            self.y0 = self.y
            self.theta_z0 = self.theta_z

    def __init__(self):
        node_name = "move_square"
        self.startup = True
        self.turn = False
        self.sides = 0

        rospy.init_node(node_name, anonymous=True)
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        self.sub = rospy.Subscriber("odom", Odometry, self.callback_function)
        self.rate = rospy.Rate(25)

        self.x = 0.0; self.y = 0.0; self.theta_z = 0.0
        self.x0 = 0.0; self.y0 = 0.0; self.theta_z0 = 0.0

        self.vel = Twist()
        self.ctrl_c = False
        rospy.on_shutdown(self.shutdownhook)
        rospy.loginfo(f"the {node_name} node has been initialised...")

    def shutdownhook(self):
        self.pub.publish(Twist())
        self.ctrl_c = True

    def main_loop(self):
        while not self.ctrl_c:
            if self.startup:
                self.vel = Twist()
            elif self.turn:
                turned = atan2(sin(self.theta_z - self.theta_z0), cos(self.theta_z - self.theta_z0))
                if abs(turned) >= pi / 2 - 0.01:
                    self.vel = Twist()
                    self.turn = False
                    self.x0 = self.x
                    self.y0 = self.y
                    self.sides += 1
                else:
                    self.vel = Twist()
                    self.vel.angular.z = 0.3 if abs(turned) < pi / 2 - 0.15 else 0.08
            else:
                moved = sqrt((self.x - self.x0) ** 2 + (self.y - self.y0) ** 2)
                if moved >= 1.0 - 0.005:
                    self.vel = Twist()
                    self.turn = True
                    self.theta_z0 = self.theta_z
                else:
                    self.vel = Twist()
                    self.vel.linear.x = 0.2 if moved < 0.9 else 0.05
            if self.sides == 8:
                self.pub.publish(Twist())
                rospy.loginfo("Two loops complete!")
                break
            self.pub.publish(self.vel)
            self.rate.sleep()


if __name__ == '__main__':
    node = Square()
    try:
        node.main_loop()
    except rospy.ROSInterruptException:
        pass
