"""Probe: an exception in a callback prints rospy's 'bad callback' block and the node carries on; spin ends at
shutdown."""
import rospy
from std_msgs.msg import String


def bad(msg):
    raise ValueError("student bug in callback " + msg.data)


rospy.init_node("badcb")
rospy.Subscriber("/words", String, bad)
rospy.spin()
print("spin returned", rospy.is_shutdown())
