#!/usr/bin/env python3
"""Probe 31 (issue 28 item 8): a latched message reaches every later subscriber of the node, at once, in the thread
that creates it (rospy's add_callback replays each latched connection's last message), and wait_for_message gets it."""
import threading

import rospy
from std_msgs.msg import String

rospy.init_node("p31_latched_subscribers")
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
pub = rospy.Publisher("/p31_latched", String, queue_size=1, latch=True)
plain = rospy.Publisher("/p31_plain", String, queue_size=1)
rospy.sleep(0.5)
pub.publish(String("first"))
pub.publish(String("second"))
plain.publish(String("plain"))
first = []
rospy.Subscriber("/p31_latched", String, lambda m: first.append(m.data))
plain_first = []
rospy.Subscriber("/p31_plain", String, lambda m: plain_first.append(m.data))
rospy.sleep(0.5)
print("first subscriber got", first)
msg = rospy.wait_for_message("/p31_latched", String, timeout=1.0)
print("wait_for_message on the latched topic got", msg.data, "t=%.3f" % (rospy.get_time() - T0))
later = []
rospy.Subscriber("/p31_latched", String,
                 lambda m, arg: later.append((m.data, arg, threading.current_thread().name,
                                              m._connection_header["latching"], m._connection_header["callerid"])),
                 "arg")
print("later subscriber got at once", later)
plain_later = []
rospy.Subscriber("/p31_plain", String, lambda m: plain_later.append(m.data))
print("later subscriber of the plain topic got at once", plain_later)
pub.publish(String("third"))
rospy.sleep(0.3)
third = []
rospy.Subscriber("/p31_latched", String, lambda m: third.append(m.data))
print("after a third message: first", first, "later", [m[0] for m in later], "newest subscriber", third)
pub.unregister()
rospy.sleep(0.3)
gone = []
rospy.Subscriber("/p31_latched", String, lambda m: gone.append(m.data))
print("subscriber after the publisher unregistered got", gone)
try:
    rospy.wait_for_message("/p31_plain", String, timeout=0.5)
    print("wait_for_message on the plain topic returned")
except rospy.ROSException as e:
    print("wait_for_message on the plain topic !!", e)
