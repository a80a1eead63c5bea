#!/usr/bin/env python3
# Spiral cleaning, as clebercoutof/turtlesim_cleaner's spiralClean. Flaw: the walls are checked once a second (the
# loop runs at 1 Hz while the speed grows to metres per second), and only the top and right ones.
import rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose

pose = Pose()


def poseCallback(msg):
    global pose
    pose = msg


def spiralClean():
    vel_msg = Twist()
    loop_rate = rospy.Rate(1)
    wk = 4
    rk = 0
    while pose.x < 10.5 and pose.y < 10.5:
        rk = rk + 1
        vel_msg.linear.x = rk
        vel_msg.angular.z = wk
        velocity_publisher.publish(vel_msg)
        loop_rate.sleep()
    vel_msg.linear.x = 0
    vel_msg.angular.z = 0
    velocity_publisher.publish(vel_msg)


if __name__ == '__main__':
    rospy.init_node('turtlesim_cleaner', anonymous=True)
    velocity_publisher = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
    pose_subscriber = rospy.Subscriber('/turtle1/pose', Pose, poseCallback)
    rospy.sleep(1.0)
    spiralClean()
