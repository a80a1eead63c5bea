#!/usr/bin/env python3
"""Probe 26 (issue 9 item 9): /use_sim_time before init_node, tuples read back as lists, set_param(None)."""
import rospy


def err(e):
    return "%s.%s: %s" % (type(e).__module__, type(e).__name__, e)


print("use_sim_time before init_node", rospy.get_param("/use_sim_time"))
rospy.init_node("p26_params")
rospy.set_param("~tup", (1, 2.5, "x"))
value = rospy.get_param("~tup")
print("tuple reads back as", value, type(value).__name__)
rospy.set_param("~nested", {"a": (1, 2)})
print("nested tuple reads back as", rospy.get_param("~nested"))
try:
    rospy.set_param("~none", None)
    print("set_param(None) ok", rospy.get_param("~none"))
except Exception as e:
    print("set_param(None) !!", err(e))
print("has ~none", rospy.has_param("~none"))
