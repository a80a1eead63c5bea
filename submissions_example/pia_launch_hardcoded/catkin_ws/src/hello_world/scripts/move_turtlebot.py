#!/usr/bin/env python3
"""move_turtlebot.py LIN ANG DIST: drive until the odometry x reaches DIST, then stop (seed 003)."""

import sys

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

robot_x = None
pub = None
done = False


def pose_callback(msg):
    global robot_x, done
    # Reading x position from the Odometry message
    robot_x = msg.pose.pose.position.x
    if not done and robot_x >= distance:
        done = True
        pub.publish(Twist())  # stop at once, without waiting for the loop


def move_turtle(lin_vel, ang_vel):
    global pub
    rospy.init_node('move_turtlebot', anonymous=False)
    # The TurtleBot3 listens on /cmd_vel
    pub = rospy.Publisher('/cmd_vel', Twist, queue_size=10)
    rospy.Subscriber('/odom', Odometry, pose_callback)
    rospy.on_shutdown(lambda: pub.publish(Twist()))
    rate = rospy.Rate(10)  # 10hz
    vel = Twist()
    vel.linear.x = lin_vel
    vel.angular.z = ang_vel
    while not rospy.is_shutdown():
        if done:
            rospy.loginfo("Robot Reached destination")
            rospy.logwarn("Stopping robot")
            break
        if robot_x is not None:
            pub.publish(vel)
        rate.sleep()
    pub.publish(Twist())  # leave the robot stopped: the base keeps the last command


if __name__ == '__main__':
    distance = float(sys.argv[3])
    try:
        move_turtle(float(sys.argv[1]), float(sys.argv[2]))
    except rospy.ROSInterruptException:
        pass
