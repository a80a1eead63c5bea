#!/usr/bin/env python3
# Go to goal (turtlesim). Flaw: the control loop never ends; the proportional controller keeps publishing tiny
# commands forever instead of stopping at a tolerance.
import math

import rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class TurtleBot:
    def __init__(self):
        rospy.init_node('turtlebot_controller', anonymous=True)
        self.velocity_publisher = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
        self.pose_subscriber = rospy.Subscriber('/turtle1/pose', Pose, self.update_pose)
        self.pose = None
        self.rate = rospy.Rate(10)

    def update_pose(self, data):
        self.pose = data

    def euclidean_distance(self, goal):
        return math.sqrt((goal.x - self.pose.x) ** 2 + (goal.y - self.pose.y) ** 2)

    def steering_angle(self, goal):
        return math.atan2(goal.y - self.pose.y, goal.x - self.pose.x)

    def move2goal(self):
        goal = Pose()
        goal.x = float(input("Set your x goal: "))
        goal.y = float(input("Set your y goal: "))
        while self.pose is None:
            self.rate.sleep()
        vel_msg = Twist()
        while not rospy.is_shutdown():
            error = self.steering_angle(goal) - self.pose.theta
            error = math.atan2(math.sin(error), math.cos(error))
            vel_msg.angular.z = 4 * error
            vel_msg.linear.x = 1.5 * self.euclidean_distance(goal) if abs(error) < 0.5 else 0.0
            self.velocity_publisher.publish(vel_msg)
            self.rate.sleep()


if __name__ == '__main__':
    try:
        TurtleBot().move2goal()
    except rospy.ROSInterruptException:
        pass
