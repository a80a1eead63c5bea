#!/usr/bin/env python3
# Task 1: figure of eight by timing. Bug: the second loop turns the same way as the first.
import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion

x0 = None
pose = None


def odom_cb(msg):
    global x0, pose
    q = msg.pose.pose.orientation
    yaw = euler_from_quaternion([q.x, q.y, q.z, q.w])[2]
    pose = (msg.pose.pose.position.x, msg.pose.pose.position.y, yaw)
    if x0 is None:
        x0 = pose


def main():
    rospy.init_node('figure_eight')
    pub = rospy.Publisher('/cmd_vel', Twist, queue_size=10)
    rospy.Subscriber('/odom', Odometry, odom_cb)
    rospy.on_shutdown(lambda: pub.publish(Twist()))
    rate = rospy.Rate(10)
    while x0 is None and not rospy.is_shutdown():
        rate.sleep()

    loop_time = 2 * math.pi / 0.2   # one circle at 0.2 rad/s
    start = rospy.get_time()
    ticks = 0
    while not rospy.is_shutdown():
        t = rospy.get_time() - start
        vel = Twist()
        if t < 2 * loop_time:
            vel.linear.x = 0.1
            vel.angular.z = 0.2          # should be -0.2 for the second loop
        pub.publish(vel)
        if ticks % 10 == 0:
            dx, dy = pose[0] - x0[0], pose[1] - x0[1]
            dyaw = math.degrees(math.atan2(math.sin(pose[2] - x0[2]), math.cos(pose[2] - x0[2])))
            rospy.loginfo("x={:.2f} [m], y={:.2f} [m], yaw={:.1f} [degrees].".format(dx, dy, dyaw))
        ticks += 1
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
