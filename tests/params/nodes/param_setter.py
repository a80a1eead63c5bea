#!/usr/bin/env python3
"""Sets, replaces and deletes shared parameters at known times, printing the time of each change."""
import rospy

rospy.init_node("setter")
rospy.sleep(0.5)
rospy.set_param("/shared/value", 42)
rospy.set_param("shared/ns", {"a": 1, "b": [1, 2.5, "x"]})
rospy.delete_param("/shared/gone")
print("set %.3f" % rospy.get_time())
rospy.sleep(0.3)
rospy.set_param("/shared/ns/c", True)  # into the namespace set above
rospy.set_param("/shared/value", 43)
rospy.delete_param("/shared/value")
rospy.set_param("/shared/value", 44)
print("changed %.3f" % rospy.get_time())
try:
    rospy.delete_param("/shared/never")
except KeyError as exc:
    print("delete missing: KeyError %s" % exc)
