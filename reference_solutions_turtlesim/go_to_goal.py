#!/usr/bin/env python3
"""turtlesim: drive turtle1 to the goal typed on stdin (x, then y) with a proportional controller, then stop."""
import math

import rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose

TOLERANCE = 0.05  # metres

pose = None


def on_pose(msg):
    global pose
    pose = msg


def main():
    rospy.init_node("go_to_goal")
    goal_x = float(input("goal x: "))
    goal_y = float(input("goal y: "))
    pub = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=10)
    rospy.Subscriber("turtle1/pose", Pose, on_pose)
    rate = rospy.Rate(20)
    while pose is None and not rospy.is_shutdown():
        rate.sleep()
    cmd = Twist()
    while not rospy.is_shutdown():
        distance = math.hypot(goal_x - pose.x, goal_y - pose.y)
        if distance < TOLERANCE:
            break
        heading = math.atan2(goal_y - pose.y, goal_x - pose.x)
        error = math.atan2(math.sin(heading - pose.theta), math.cos(heading - pose.theta))
        cmd.angular.z = 4.0 * error
        cmd.linear.x = min(1.5 * distance, 2.0) if abs(error) < 0.5 else 0.0
        pub.publish(cmd)
        rate.sleep()
    pub.publish(Twist())
    rospy.loginfo("reached (%.2f, %.2f)", pose.x, pose.y)


if __name__ == "__main__":
    main()
