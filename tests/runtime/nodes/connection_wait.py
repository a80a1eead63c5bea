#!/usr/bin/env python3
# Waits until the robot has connected, then publishes a single Twist and spins: the robot must get it.
import rospy
from geometry_msgs.msg import Twist

rospy.init_node("connection_wait")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
rate = rospy.Rate(10)
while pub.get_num_connections() < 1:
    rate.sleep()
cmd = Twist()
cmd.linear.x = 0.2
pub.publish(cmd)
rospy.spin()
