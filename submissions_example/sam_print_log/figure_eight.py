#!/usr/bin/env python3
# Task 1: figure of eight by timing. Bug: prints the pose with print() and three decimals, so the lines are not
# logged at INFO level and do not have the format asked for.
import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion

start = None
now = None


def callback(msg):
    global start, now
    q = msg.pose.pose.orientation
    now = (msg.pose.pose.position.x, msg.pose.pose.position.y, euler_from_quaternion([q.x, q.y, q.z, q.w])[2])
    if start is None:
        start = now


def relative():
    dx, dy = now[0] - start[0], now[1] - start[1]
    c, s = math.cos(start[2]), math.sin(start[2])
    dyaw = math.atan2(math.sin(now[2] - start[2]), math.cos(now[2] - start[2]))
    return c * dx + s * dy, -s * dx + c * dy, math.degrees(dyaw)


rospy.init_node('figure_eight')
pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
rospy.Subscriber('odom', Odometry, callback)
rospy.on_shutdown(lambda: pub.publish(Twist()))
rate = rospy.Rate(10)
while start is None and not rospy.is_shutdown():
    rate.sleep()

LOOP = 2 * math.pi / 0.2
t0 = rospy.Time.now().to_sec()
count = 0
while not rospy.is_shutdown():
    t = rospy.Time.now().to_sec() - t0
    twist = Twist()
    if t < LOOP:
        twist.linear.x, twist.angular.z = 0.1, 0.2
    elif t < 2 * LOOP:
        twist.linear.x, twist.angular.z = 0.1, -0.2
    pub.publish(twist)
    if count % 10 == 0:
        x, y, yaw = relative()
        print("x={:.3f} [m], y={:.3f} [m], yaw={:.3f} [degrees].".format(x, y, yaw))
    count += 1
    rate.sleep()
