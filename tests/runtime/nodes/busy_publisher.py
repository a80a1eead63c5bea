#!/usr/bin/env python3
# The Husky tutorial's pattern: publish in a loop with no sleep until the odometry says 1.5 m.
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

x = 0.0


def odom(msg):
    global x
    x = msg.pose.pose.position.x


rospy.init_node("busy_publisher")
rospy.Subscriber("/odom", Odometry, odom)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
cmd = Twist()
cmd.linear.x = 0.2
while not rospy.is_shutdown() and x < 1.5:
    pub.publish(cmd)
pub.publish(Twist())
rospy.loginfo("stopped at x=%.3f", x)
