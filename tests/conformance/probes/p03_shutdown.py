#!/usr/bin/env python3
"""Probe 3: Ctrl+C under sim time. Run with 'uncaught' or 'caught'; SIGINT arrives 1.05 s after the origin.

Hook order and arguments, is_shutdown() inside hooks, a raising hook, a hook that publishes a zero Twist,
rate.sleep() raising ROSInterruptException (uncaught: exit 1), and what works after shutdown.
"""
import sys

import rospy
from geometry_msgs.msg import Twist

mode = sys.argv[1] if len(sys.argv) > 1 else "uncaught"
rospy.init_node("p03_shutdown")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
n = 0


def hook1(*args):
    print("hook1 args", args, "is_shutdown", rospy.is_shutdown(), "requested", rospy.core.is_shutdown_requested(),
          "n", n)


def hook2():
    print("hook2 raising")
    raise RuntimeError("boom in hook")


def hook3():
    print("hook3 publishing zero Twist; is_shutdown", rospy.is_shutdown())
    pub.publish(Twist())


def stop():
    print("stop() called by on_shutdown(stop())")


try:
    rospy.on_shutdown(stop())
except Exception as e:
    print("on_shutdown(stop()) !! %s: %s" % (type(e).__name__, e))
rospy.on_shutdown(hook1)
rospy.on_shutdown(hook2)
rospy.on_shutdown(hook3)
print("mro", [c.__name__ for c in rospy.ROSInterruptException.__mro__])
print("issubclass(ROSTimeMovedBackwardsException, ROSInterruptException)",
      issubclass(rospy.exceptions.ROSTimeMovedBackwardsException, rospy.ROSInterruptException))

rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
rospy.sleep(0.2)  # let the robot connect to /cmd_vel (real rospy drops messages sent in the first ~50-100 ms)
r = rospy.Rate(10)
t = Twist()
t.linear.x = 0.1


def loop():
    global n
    while not rospy.is_shutdown():
        t.linear.z = n
        pub.publish(t)
        n += 1
        r.sleep()


if mode == "caught":
    try:
        loop()
    except rospy.ROSInterruptException as e:
        print("caught %s.%s: %s" % (type(e).__module__, type(e).__name__, e))
    print("after loop is_shutdown", rospy.is_shutdown(), "n", n)
    print("publish after shutdown returns", pub.publish(Twist()))
    for label, fn in [("rospy.sleep(0.1)", lambda: rospy.sleep(0.1)), ("rospy.sleep(0)", lambda: rospy.sleep(0)),
                      ("rate.sleep()", r.sleep)]:
        try:
            fn()
            print(label, "returned")
        except Exception as e:
            print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))
    rospy.on_shutdown(lambda: print("late hook ran immediately"))
    print("after late on_shutdown")
    rospy.spin()
    print("spin returned; is_shutdown", rospy.is_shutdown())
    p2 = rospy.Publisher("/other", Twist, queue_size=1)
    print("new publisher after shutdown", p2.resolved_name)
    print("end")
else:
    loop()
    print("not reached")
