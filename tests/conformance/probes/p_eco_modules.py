#!/usr/bin/env python3
"""Probe (issue 9 item 5): the ROS 1 modules real Noetic nodes import besides rospy: tf2_ros with a live /tf and a
node's own (static) broadcasters, message_filters on /odom, roslib, nav_msgs.srv, and rospy's graph calls."""
import rospy

import message_filters
import roslib
import rospkg
import tf2_ros
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Odometry
from nav_msgs.srv import GetMap, GetPlan, GetPlanRequest


def transform(parent, child, x, stamp):
    t = TransformStamped()
    t.header.frame_id, t.header.stamp, t.child_frame_id = parent, stamp, child
    t.transform.translation.x = x
    t.transform.rotation.w = 1.0
    return t


rospy.init_node("eco_modules")
buf = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buf)
# First let the listener fill the buffer: an /odom message older than the buffer's first /tf would make real tf2 raise
# ExtrapolationException ("into the past"), as it did in one real run.
buf.can_transform("odom", "base_footprint", rospy.Time(0), rospy.Duration(5.0))
# The robot may still be moving from an earlier probe: compare with /odom at the same stamp, not with numbers.
odom = rospy.wait_for_message("/odom", Odometry, timeout=5.0)
found = buf.lookup_transform("odom", "base_footprint", odom.header.stamp, rospy.Duration(2.0))
same = (abs(found.transform.translation.x - odom.pose.pose.position.x) < 1e-9
        and abs(found.transform.rotation.w - odom.pose.pose.orientation.w) < 1e-9)
print("lookup", found.header.frame_id, found.child_frame_id, "matches /odom", same,
      "stamp", found.header.stamp == odom.header.stamp)
latest = buf.lookup_transform("odom", "base_footprint", rospy.Time(0))
print("latest stamped", latest.header.stamp > rospy.Time(0))
print("can_transform", buf.can_transform("odom", "base_footprint", rospy.Time(0)))
print("can_transform unknown", buf.can_transform("odom", "nope", rospy.Time(0)))
try:
    buf.lookup_transform("odom", "nope", rospy.Time(0))
except tf2_ros.LookupException as e:
    print("LookupException", isinstance(e, tf2_ros.TransformException), e)
try:
    buf.lookup_transform("odom", "base_footprint", rospy.Time.now() + rospy.Duration(5.0))
except tf2_ros.ExtrapolationException as e:
    print("ExtrapolationException", isinstance(e, tf2_ros.TransformException))

static = tf2_ros.StaticTransformBroadcaster()
static.sendTransform(transform("base_footprint", "probe_static", 0.5, rospy.Time.now()))
moving = tf2_ros.TransformBroadcaster()
rate = rospy.Rate(10)
for _ in range(5):
    moving.sendTransform(transform("base_footprint", "probe_moving", 0.25, rospy.Time.now()))
    rate.sleep()
for child in ("probe_static", "probe_moving"):
    t = buf.lookup_transform("base_footprint", child, rospy.Time(0), rospy.Duration(1.0))
    print("own frame", child, round(t.transform.translation.x, 3))

counts = {"exact": 0, "approximate": 0}
odom_a = message_filters.Subscriber("/odom", Odometry)
odom_b = message_filters.Subscriber("/odom", Odometry)
exact = message_filters.TimeSynchronizer([odom_a, odom_b], 10)
exact.registerCallback(lambda a, b: counts.__setitem__("exact", counts["exact"] + (a.header.stamp == b.header.stamp)))
approx = message_filters.ApproximateTimeSynchronizer([odom_a, odom_b], 10, 0.05)
approx.registerCallback(lambda a, b: counts.__setitem__("approximate", counts["approximate"] + 1))
cache = message_filters.Cache(message_filters.Subscriber("/odom", Odometry), 5)
rospy.sleep(1.0)
print("synchronised about 30 in 1 s", all(20 <= n <= 40 for n in counts.values()))
print("cache holds", len(cache.cache_msgs), "latest is last", cache.getLast() is cache.cache_msgs[-1])

try:
    roslib.load_manifest("no_such_package_here")
except rospkg.ResourceNotFound as e:
    print("load_manifest unknown", type(e).__name__, e.args[0])
print("GetPlan", GetPlan._type, GetPlan._md5sum, GetMap._md5sum, GetPlanRequest().tolerance)
topics = rospy.get_published_topics()
print("published", ["/odom", "nav_msgs/Odometry"] in topics, ["/clock", "rosgraph_msgs/Clock"] in topics,
      ["/tf_static", "tf2_msgs/TFMessage"] in topics)
print("remap_name", rospy.remap_name("chatter"), "cached", rospy.get_param_cached("/use_sim_time"))
print("SubscribeListener", [m for m in dir(rospy.SubscribeListener) if not m.startswith("_")])
