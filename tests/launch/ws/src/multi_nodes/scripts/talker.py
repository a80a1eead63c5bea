#!/usr/bin/env python3
"""Publishes numbered greetings on `chatter` at ~rate Hz; the greeting comes from the global /greeting param."""
import rospy
from std_msgs.msg import String

rospy.init_node("talker")
pub = rospy.Publisher("chatter", String, queue_size=10)
rate = rospy.Rate(rospy.get_param("~rate"))
greeting = rospy.get_param("/greeting")
count = 0
while not rospy.is_shutdown():
    text = "%s %d" % (greeting, count)
    pub.publish(String(data=text))
    print("said", text)
    count += 1
    rate.sleep()
