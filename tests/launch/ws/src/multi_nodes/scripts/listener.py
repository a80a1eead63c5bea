#!/usr/bin/env python3
"""Echoes what it hears on `chatter` to `heard`, and prints its name, namespace and what it heard."""
import rospy
from std_msgs.msg import String

rospy.init_node("listener")
pub = rospy.Publisher("heard", String, queue_size=10)


def callback(msg):
    print("heard", msg.data)
    pub.publish(String(data=rospy.get_name() + " heard " + msg.data))


rospy.Subscriber("chatter", String, callback)
print("I am", rospy.get_name(), "in", rospy.get_namespace(), "greeting", rospy.get_param("/greeting"))
rospy.spin()
