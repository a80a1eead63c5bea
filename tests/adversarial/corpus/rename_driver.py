#!/usr/bin/env python3
"""Re-sends INIT under the scripted driver's name, then drives far over the speed limit."""
import rospy
import rosgrade_channel as ch
from geometry_msgs.msg import Twist
from rosgrade_node import runtime

rospy.init_node("mover")
runtime.link.send_json(ch.INIT, {"name": "/rosgrade_driver", "anonymous": False, "log_level": None,
                                 "disable_signals": False})
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
cmd = Twist()
cmd.linear.x = 5.0
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    pub.publish(cmd)
    rate.sleep()
