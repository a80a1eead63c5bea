"""Probe: Ctrl+C (SHUTDOWN) during Rate.sleep: hooks in order with is_shutdown() False, then the sleep raises.
With argument 'catch' the exception is caught; the probe then checks that later publishes and sleeps behave."""
import sys

import rospy
from std_msgs.msg import String

rospy.init_node("hooks")
pub = rospy.Publisher("/chatter", String, queue_size=10)


def first():
    print("first", rospy.is_shutdown(), rospy.core.is_shutdown_requested())
    pub.publish(String(data="zero"))


def second():
    raise RuntimeError("boom in hook")


def third():
    print("third", rospy.is_shutdown())


rospy.on_shutdown(first)
rospy.on_shutdown(second)
rospy.on_shutdown(third)
rate = rospy.Rate(10)


def loop():
    while not rospy.is_shutdown():
        pub.publish(String(data="tick"))
        rate.sleep()


if sys.argv[1:] == ["catch"]:
    try:
        loop()
    except rospy.ROSInterruptException as exc:
        print("caught", repr(str(exc)), rospy.is_shutdown())
    pub.publish(String(data="dropped"))
    rospy.on_shutdown(lambda: print("late hook ran"))
    try:
        rospy.sleep(1.0)
    except rospy.ROSInterruptException:
        print("sleep after shutdown raised")
else:
    loop()
