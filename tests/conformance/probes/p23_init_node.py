#!/usr/bin/env python3
"""Probe 23 (issue 9 item 4): topics created before init_node connect while it runs (callbacks, publishers)."""
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf2_msgs.msg import TFMessage

calls = []
errors = []
returned = [False]


def on_odom(msg):
    calls.append(returned[0])
    if not returned[0] and not errors:
        try:
            rospy.get_time()
        except Exception as e:
            errors.append("%s.%s: %s" % (type(e).__module__, type(e).__name__, e))


def on_tf(msg):
    if not returned[0] and not logged:
        logged.append(1)
        rospy.loginfo("a log line from a callback during init_node")
        rospy.Time.now()  # raises: rospy reports it as a bad callback


logged = []
rospy.Subscriber("/odom", Odometry, on_odom, queue_size=10)
rospy.Subscriber("/tf", TFMessage, on_tf)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
rospy.init_node("p23_init_node")
returned[0] = True
early = len(calls)
cmd = Twist()
cmd.linear.x = 0.12
pub.publish(cmd)
print("callbacks ran before init_node returned", 1 <= early <= 8)
print("rospy time in a callback during init_node !!", errors[0] if errors else None)
print("publisher created before init_node has connections", pub.get_num_connections())
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
rospy.sleep(1.0)
print("callbacks after init_node", len(calls) - early > 25)
