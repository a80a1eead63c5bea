#!/usr/bin/env python3
"""rospy's parameter calls against the fake grader: what each sends, and what reads back at once."""
import xmlrpc.client

import rospy

rospy.set_param("/before_init", 1)  # rosmaster takes it before the node registers, as real rospy lets it
rospy.init_node("probe", argv=["probe.py", "_rate:=5"])
rospy.set_param("~gain", (1, 2.5))  # a tuple: XML-RPC gives back a list
rospy.set_param("plain", {"x": "y"})
rospy.set_param("/blob", xmlrpc.client.Binary(b"\x00"))  # JSON cannot carry it: this node's only
rospy.delete_param("plain/x")
try:
    rospy.delete_param("/missing")
except KeyError as exc:
    print("missing %s" % exc)
try:
    rospy.set_param("/none", None)
except TypeError:
    print("none refused")
print("gain %r plain %r blob %r" % (rospy.get_param("~gain"), rospy.get_param("plain"), rospy.has_param("/blob")))
print("start %r" % rospy.get_param("/given"))
