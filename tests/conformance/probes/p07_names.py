#!/usr/bin/env python3
"""Probe 7: argv, myargv, remapping, private parameters and namespaces (run with remap arguments)."""
import os
import sys

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

print("argv", sys.argv[1:])
print("myargv before init", rospy.myargv()[1:])
print("myargv(argv=...)", rospy.myargv(argv=["x", "a:=b", "c", "_p:=1", "__ns:=q"]))
print("ROS_NAMESPACE", os.environ.get("ROS_NAMESPACE"))
rospy.init_node("p07_names")
print("argv after init", sys.argv[1:])
print("myargv after init", rospy.myargv()[1:])
print("get_name", rospy.get_name(), "get_namespace", rospy.get_namespace(), "caller_id", rospy.get_caller_id())
for name in ("cmd_vel", "/cmd_vel", "~odom", "odom", "/odom", "a/b", "~", "foo//bar"):
    try:
        print("resolve_name(%r)" % name, rospy.resolve_name(name))
    except Exception as e:
        print("resolve_name(%r) !! %s: %s" % (name, type(e).__name__, e))
for name in ("cmd_vel", "/cmd_vel", "~cmd"):
    p = rospy.Publisher(name, Twist, queue_size=1)
    print("Publisher(%r)" % name, p.name, p.resolved_name, p.type, p.name == p.resolved_name)
for name in ("odom", "/odom"):
    s = rospy.Subscriber(name, Odometry, lambda m: None)
    print("Subscriber(%r)" % name, s.name, s.resolved_name, s.type)
for key in ("~speed", "speed", rospy.get_name() + "/speed", "~missing", "/use_sim_time", "~flag", "~text", "~num"):
    try:
        v = rospy.get_param(key)
        print("get_param(%r)" % key, repr(v), type(v).__name__)
    except Exception as e:
        print("get_param(%r) !! %s: %s" % (key, type(e).__name__, e))
print("get_param default", rospy.get_param("~missing", 1.5))
print("has_param ~speed", rospy.has_param("~speed"))
