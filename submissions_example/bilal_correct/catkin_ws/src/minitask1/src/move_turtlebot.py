#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
import sys

robot_x = None


def pose_callback(msg):
    global robot_x
    robot_x = msg.pose.pose.position.x


def move_turtle(lin_vel, ang_vel, distance):
    rospy.init_node('move_turtlebot', anonymous=False)
    pub = rospy.Publisher('/cmd_vel', Twist, queue_size=10)
    rospy.Subscriber('/odom', Odometry, pose_callback)
    rate = rospy.Rate(50)  # check often so the robot does not overshoot
    vel = Twist()
    while not rospy.is_shutdown():
        if robot_x is None:
            rate.sleep()
            continue
        if robot_x >= distance:
            rospy.loginfo("Robot Reached destination")
            break
        vel.linear.x = lin_vel
        vel.angular.z = ang_vel
        pub.publish(vel)
        rate.sleep()
    rospy.logwarn("Stopping robot")
    pub.publish(Twist())
    rospy.sleep(1.0)


if __name__ == '__main__':
    try:
        move_turtle(float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]))
    except rospy.ROSInterruptException:
        pass
