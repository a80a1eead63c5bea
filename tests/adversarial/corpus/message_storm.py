#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist
rospy.init_node("storm")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
msg = Twist()
msg.linear.x = 0.1
while not rospy.is_shutdown():
    pub.publish(msg)
