#!/usr/bin/env python3
"""Reads the shared parameters every 10 ms and prints each value it sees change, with the time it saw it."""
import rospy

rospy.init_node("reader")
last = object()
until = rospy.get_time() + 1.5
while rospy.get_time() < until:
    seen = (rospy.get_param("/shared/value", None), rospy.has_param("/shared/gone"),
            rospy.get_param("/shared/ns", None))
    if seen != last:
        print("%.3f %r" % (rospy.get_time(), seen))
        last = seen
    rospy.sleep(0.01)
print("names %s" % sorted(n for n in rospy.get_param_names() if n.startswith("/shared")))
