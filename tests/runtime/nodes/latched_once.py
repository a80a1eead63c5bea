#!/usr/bin/env python3
# Publishes one latched Twist right after creating the publisher, then spins: the robot must still get it.
import rospy
from geometry_msgs.msg import Twist

rospy.init_node("latched_once")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
cmd = Twist()
cmd.linear.x = 0.2
pub.publish(cmd)
rospy.spin()
