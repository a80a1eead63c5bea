"""Probe: main-thread busy waits on data set by a callback, with no library call and with time.time() calls."""
import time

import rospy
from std_msgs.msg import Float64

state = {"value": None, "count": 0}


def callback(msg):
    state["value"] = msg.data
    state["count"] += 1


rospy.init_node("busywait")
rospy.Subscriber("/value", Float64, callback)
while state["value"] is None:
    pass
print("first", state["value"], rospy.get_rostime().to_nsec())
while state["count"] < 3:
    time.time()
print("third", state["value"], rospy.get_rostime().to_nsec())
