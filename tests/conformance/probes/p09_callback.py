#!/usr/bin/env python3
"""Probe 9: subscriber callbacks run in their own thread while the main thread busy-waits on a variable."""
import threading

import rospy
from nav_msgs.msg import Odometry
from tf2_msgs.msg import TFMessage

count = 0
stamps = []
info = {}


def on_odom(msg, arg):
    global count
    if not info:
        th = threading.current_thread()
        info.update(thread=th.name, daemon=th.daemon, main=th is threading.main_thread(), arg=arg,
                    type=type(msg).__name__, frame=msg.header.frame_id, child=msg.child_frame_id,
                    cov=len(msg.pose.covariance), stamp_type=type(msg.header.stamp).__name__,
                    header_keys=sorted(getattr(msg, "_connection_header", {}) or {}),
                    callerid=getattr(msg, "_connection_header", {}).get("callerid"))
    stamps.append(msg.header.stamp.to_nsec())
    count += 1


tf_calls = []


def bad_tf(msg):
    tf_calls.append(1)
    if len(tf_calls) == 1:
        raise ValueError("student bug in callback")


rospy.init_node("p09_callback")
rospy.Subscriber("/odom", Odometry, on_odom, callback_args="extra", queue_size=1)
rospy.Subscriber("/tf", TFMessage, bad_tf)
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
while count < 3:
    pass
print("busy wait saw count >= 3", count >= 3)
for k in sorted(info):
    print("callback", k, info[k])

# A subscriber created while the clock runs: how soon its first message arrives (real: the subscriber connects to
# the existing publisher at once, so the next 30 Hz sample arrives).
late = []
subscribed_at = rospy.get_time()
rospy.Subscriber("/odom", Odometry, lambda m: late.append(rospy.get_time()) if not late else None)
rospy.sleep(1.5)
print("late subscriber got a message", bool(late))
print("late subscriber's first message within 0.045 s", bool(late) and late[0] - subscribed_at <= 0.045)
t0 = T0 + 0.2
window = [s for s in stamps if int(round(t0 * 1e9)) <= s < int(round((t0 + 1.0) * 1e9))]
print("odom stamps in a 1.0 s window", len(window))
gaps = sorted({round((b - a) / 1e9, 4) for a, b in zip(stamps, stamps[1:])})
print("odom stamp gaps", gaps)
print("tf callbacks > 30", len(tf_calls) > 30)
print("main thread", threading.current_thread().name)
