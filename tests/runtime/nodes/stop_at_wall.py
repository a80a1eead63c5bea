#!/usr/bin/env python3
# A first obstacle-avoidance node: drive forward until the laser sees something within 0.5 m ahead, then stop.
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

ahead = float("inf")


def scan(msg):
    global ahead
    front = list(msg.ranges[:15]) + list(msg.ranges[-15:])
    ahead = min(front)


rospy.init_node("stop_at_wall")
rospy.Subscriber("/scan", LaserScan, scan)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
rate = rospy.Rate(10)
go = Twist()
go.linear.x = 0.2
while not rospy.is_shutdown() and ahead > 0.5:
    pub.publish(go)
    rate.sleep()
pub.publish(Twist())
rospy.loginfo("stopped %.2f m from the wall", ahead)
