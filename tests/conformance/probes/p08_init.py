#!/usr/bin/env python3
"""Probe 8: init_node rules. Variants: 'bad' (bad names), 'twice', 'anon'."""
import os
import re
import sys

import rospy

mode = sys.argv[1]


def attempt(label, fn):
    try:
        fn()
        print(label, "ok", rospy.get_name())
    except Exception as e:
        print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))


print("get_name before init", rospy.get_name())
if mode == "bad":
    attempt("init_node('/my_node')", lambda: rospy.init_node("/my_node"))
    attempt("init_node('robot/my_node')", lambda: rospy.init_node("robot/my_node"))
    attempt("init_node('')", lambda: rospy.init_node(""))
    attempt("init_node(None)", lambda: rospy.init_node(None))
    attempt("init_node('my-node')", lambda: rospy.init_node("my-node"))
elif mode == "twice":
    attempt("init_node('a')", lambda: rospy.init_node("a"))
    attempt("init_node('a') again", lambda: rospy.init_node("a"))
    attempt("init_node('b')", lambda: rospy.init_node("b"))
    attempt("init_node('a', anonymous=True)", lambda: rospy.init_node("a", anonymous=True))
    attempt("init_node('a', log_level=rospy.INFO)", lambda: rospy.init_node("a", log_level=rospy.INFO))
elif mode == "anon":
    rospy.init_node("p08", anonymous=True)
    name = rospy.get_name()
    m = re.match(r"^/p08_(\d+)_(\d+)$", name)
    print("anonymous name matches /p08_PID_MS", bool(m))
    print("pid part is os.getpid()", bool(m) and int(m.group(1)) == os.getpid())
    print("ms part has 13 digits", bool(m) and len(m.group(2)) == 13)
    print("get_name", re.sub(r"_\d+_\d+$", "_<PID>_<MS>", name))
print("is_shutdown", rospy.is_shutdown())
