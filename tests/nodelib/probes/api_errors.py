"""Probe: publish errors, the missing-queue_size warning, private parameters, names and wait_for_message timeout."""
import rospy
from geometry_msgs.msg import Twist, Vector3
from std_msgs.msg import String

pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
try:
    pub.publish(Twist())
except rospy.ROSException as exc:
    print("before init:", exc)
rospy.init_node("api")
nq = rospy.Publisher("/other", String)
for args in ((String("x"),), ("hello",)):
    try:
        pub.publish(*args)
    except TypeError as exc:
        print("TypeError:", exc)
t = Twist()
t.linear.x = "fast"
try:
    pub.publish(t)
except rospy.ROSSerializationException as exc:
    print("ROSSerializationException:", exc)
pub.publish(linear=Vector3(1, 0, 0))
print("params", rospy.get_param("~speed"), rospy.get_param("/use_sim_time"), rospy.myargv())
print("names", rospy.get_name(), rospy.get_namespace(), pub.resolved_name, pub.get_num_connections())
try:
    rospy.wait_for_message("/nothing", String, timeout=0.5)
except rospy.ROSException as exc:
    print("wfm:", exc, rospy.get_time())
try:
    rospy.init_node("other")
except rospy.ROSException as exc:
    print("twice:", exc)
