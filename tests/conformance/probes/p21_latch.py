#!/usr/bin/env python3
"""Probe 21 (issue 9 item 2): a latched publisher's last message reaches the robot and every later subscriber."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String

rospy.init_node("p21_latch")
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
cmd = Twist()
cmd.linear.x = 0.15
pub.publish(cmd)
print("published one latched Twist right after creating the publisher")
chatter = rospy.Publisher("/p21_latched", String, queue_size=1, latch=True)
chatter.publish(String("first"))
chatter.publish(String("second"))
plain = rospy.Publisher("/p21_plain", String, queue_size=1)
plain.publish(String("not latched"))
rospy.sleep(0.5)
msg = rospy.wait_for_message("/p21_latched", String, timeout=2.0)
print("wait_for_message on the latched topic got", msg.data)
try:
    rospy.wait_for_message("/p21_plain", String, timeout=0.5)
    print("wait_for_message on the plain topic returned")
except rospy.ROSException as e:
    print("wait_for_message on the plain topic !!", e)
got = []
rospy.Subscriber("/p21_latched", String, lambda m: got.append(m.data))
rospy.sleep(0.5)
print("late subscriber got", got)
print("cmd_vel connections", pub.get_num_connections())
