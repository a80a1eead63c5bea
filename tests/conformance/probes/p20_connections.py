#!/usr/bin/env python3
"""Probe 20 (issue 9 item 1): get_num_connections() is 0 until a subscriber connects; the connection-wait pattern."""
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from std_msgs.msg import String

rospy.init_node("p20_connections")
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
nobody = rospy.Publisher("/p20_nobody", String, queue_size=1)
print("cmd_vel publisher connections at creation", pub.get_num_connections())
print("unsubscribed publisher connections at creation", nobody.get_num_connections())
lonely = rospy.Subscriber("/p20_nothing", String, lambda m: None)
odom = rospy.Subscriber("/odom", Odometry, lambda m: None)
rate = rospy.Rate(10)
waited = 0
while pub.get_num_connections() < 1 and not rospy.is_shutdown():
    rate.sleep()
    waited += 1
print("waited at least one rate period for the robot to connect", waited >= 1)
cmd = Twist()
cmd.linear.x = 0.2
pub.publish(cmd)
print("published once")
rospy.sleep(1.0)
print("cmd_vel publisher connections", pub.get_num_connections())
print("unsubscribed publisher connections after 1 s", nobody.get_num_connections())
print("odom subscriber connections", odom.get_num_connections())
print("unpublished subscriber connections", lonely.get_num_connections())
