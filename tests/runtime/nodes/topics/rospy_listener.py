#!/usr/bin/env python3
# Hears /chatter from the start, and a second subscriber from 2 s on: prints each message with its sender and time.
import rospy
from std_msgs.msg import String


def heard(name):
    def callback(msg):
        print(f"{name} {msg.data} {msg._connection_header['callerid']} {rospy.get_time():.3f}", flush=True)
    return callback


rospy.init_node("listener")
rospy.Subscriber("/chatter", String, heard("early"))
rospy.sleep(2.0)
rospy.Subscriber("/chatter", String, heard("late"))
rospy.spin()
