#!/usr/bin/env python3
import rospy
from std_msgs.msg import String
rospy.init_node("huge")
pub = rospy.Publisher("/chatter", String, queue_size=1)
rospy.sleep(0.2)
pub.publish(String(data="x" * (64 << 20)))
rospy.sleep(1.0)
