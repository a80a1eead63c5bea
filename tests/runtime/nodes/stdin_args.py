#!/usr/bin/env python3
# Arguments, remapping and stdin as a scenario gives them.
import sys

import rospy
from geometry_msgs.msg import Twist

rospy.init_node("stdin_args")
print("argv", sys.argv[1:])
print("myargv", rospy.myargv()[1:])
speed = float(input("speed? "))
pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
rospy.sleep(0.5)
cmd = Twist()
cmd.linear.x = speed
pub.publish(cmd)
rospy.sleep(1.0)
pub.publish(Twist())
