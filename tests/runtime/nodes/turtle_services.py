#!/usr/bin/env python3
"""Calls every turtlesim service from rospy: spawn and drive a second turtle, lift turtle1's pen and teleport it,
fail on purpose (a taken name, a service nobody serves, a turtle that is gone), then reset."""
import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty, Trigger
from turtlesim.srv import Kill, SetPen, SetPenRequest, Spawn, TeleportAbsolute, TeleportRelative


def attempt(label, proxy, *args, **kwds):
    """Call and print the outcome: the response, or the ServiceException's text."""
    try:
        print("%s ok %r" % (label, proxy(*args, **kwds)))
    except rospy.ServiceException as exc:
        print("%s failed: %s" % (label, exc))


rospy.init_node("turtle_services")
rospy.wait_for_service("/spawn", timeout=2.0)
spawn = rospy.ServiceProxy("/spawn", Spawn, persistent=True)
name = spawn(2.0, 3.0, 0.0, "").name
print("spawned %s at %.3f" % (name, rospy.get_time()))
rospy.ServiceProxy("/%s/teleport_absolute" % name, TeleportAbsolute).wait_for_service(timeout=1.0)
print("%s serves teleport_absolute at %.3f" % (name, rospy.get_time()))
attempt("spawn taken", spawn, x=1.0, y=1.0, theta=0.0, name="turtle1")
attempt("wrong type", rospy.ServiceProxy("/clear", Trigger))
attempt("missing", rospy.ServiceProxy("/no_such_service", Empty))
try:
    rospy.wait_for_service("/no_such_service", timeout=0.5)
except rospy.ROSException as exc:
    print("wait failed at %.3f: %s" % (rospy.get_time(), exc))

drive = rospy.Publisher("/%s/cmd_vel" % name, Twist, queue_size=1)
rospy.sleep(0.1)
forward = Twist()
forward.linear.x = 1.0
for _ in range(10):
    drive.publish(forward)
    rospy.sleep(0.1)

rospy.ServiceProxy("/turtle1/set_pen", SetPen)(SetPenRequest(off=1))
rospy.ServiceProxy("/turtle1/teleport_relative", TeleportRelative)(2.0, 0.0)
rospy.sleep(0.1)
print("pen off, moved at %.3f" % rospy.get_time())
rospy.ServiceProxy("/turtle1/teleport_absolute", TeleportAbsolute)(x=1.0, y=9.0, theta=1.5)
rospy.sleep(0.1)
attempt("kill nobody", rospy.ServiceProxy("/kill", Kill), "nobody")
print("reset at %.3f" % rospy.get_time())
rospy.ServiceProxy("/reset", Empty)()
rospy.sleep(0.1)
attempt("gone", rospy.ServiceProxy("/%s/set_pen" % name, SetPen), 255, 0, 0, 3, 0)
print("done at %.3f" % rospy.get_time())
