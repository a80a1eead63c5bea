#!/usr/bin/env python3
"""Probe 4: log formats and streams under sim time, % arguments, errors, throttle/once (about 2.1 s of sim time)."""
import sys

import rospy
from geometry_msgs.msg import Vector3

rospy.loginfo("loginfo before init_node")
rospy.logwarn("logwarn before init_node")
rospy.logerr("logerr before init_node")
print("print before init")
rospy.init_node("p04_logging")
rospy.loginfo("right after init_node")
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
rospy.loginfo("loginfo message")
rospy.logwarn("logwarn message")
rospy.logerr("logerr message")
rospy.logfatal("logfatal message")
rospy.logdebug("logdebug hidden")
rospy.loginfo("x=%.2f y=%.2f", 1.23456, 2.0)
rospy.loginfo("pct-args tuple %s", (1, 2))
rospy.loginfo("literal 100% no args")
rospy.loginfo("dict arg %(a)s", {"a": 5})
rospy.loginfo(12345)
rospy.loginfo(["a", 1])
rospy.loginfo(Vector3(1, 2, 3))
rospy.loginfo("multi\nline")
rospy.logwarn("warn %d", 7)
try:
    rospy.loginfo("bad format %d", "notanumber")
except Exception as e:
    print("bad format !! %s: %s" % (type(e).__name__, e))
try:
    rospy.loginfo("too few %s %s", 1)
except Exception as e:
    print("too few !! %s: %s" % (type(e).__name__, e))
print("print goes to stdout")
print("print to stderr", file=sys.stderr)
print("name", rospy.get_name(), rospy.get_caller_id(), rospy.get_namespace())


def helper(i):
    rospy.loginfo_throttle(0.5, "via helper %d" % i)


# Start the loop on the first clock tick at or after T0 + 0.1, however long the lines above took (real rospy
# on a slow machine can spend more than one 10 ms tick on them).
while rospy.get_time() < T0 + 0.1 - 1e-6:
    rospy.sleep(0.001)
r = rospy.Rate(10)
for i in range(21):
    rospy.loginfo_throttle(0.5, "throttle %d" % i)
    rospy.loginfo_throttle(0.5, "A%d" % i); rospy.loginfo_throttle(0.5, "B%d" % i)
    helper(i)
    helper(i)
    rospy.logwarn_once("warn once %d" % i)
    rospy.loginfo_once("info once %d" % i)
    rospy.loginfo_throttle_identical(1.0, "identical")
    rospy.logwarn_throttle(1.0, "warn throttle %d" % i)
    r.sleep()
rospy.loginfo("done")
