#!/usr/bin/env python3
"""Probe 34 (issue 28): rospy services. A call to a service not up yet fails at once and wait_for_service times out;
once the node serves it, wait_for_service returns, a call is answered (its handler in a thread of its own, in the
same sim-clock tick), a handler's ServiceException reaches the caller in rospy's words, a call inside a Timer callback
returns (rospy's callbacks have threads of their own: no executor to deadlock), and after shutdown it is gone."""
import threading

import rospy
from std_srvs.srv import SetBool, SetBoolResponse

rospy.init_node("p34_services")
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
proxy = rospy.ServiceProxy("/p34_switch", SetBool)
try:
    proxy(True)
except rospy.ServiceException as e:
    print("call before the server !!", e)
try:
    rospy.wait_for_service("/p34_switch", timeout=0.5)
except rospy.ROSException as e:
    print("wait_for_service before the server !!", e, "t=%.3f" % (rospy.get_time() - T0))


def handle(request):
    print("handler in the main thread", threading.current_thread() is threading.main_thread())
    if not request.data:
        raise rospy.ServiceException("no thanks")
    return SetBoolResponse(True, "on")


server = rospy.Service("/p34_switch", SetBool, handle)
try:
    rospy.Service("/p34_switch", SetBool, handle)
except rospy.ServiceException as e:
    print("a second Service of the name !!", e)
rospy.wait_for_service("/p34_switch", timeout=1.0)
print("wait_for_service once served returned t=%.3f" % (rospy.get_time() - T0))
sent = rospy.get_time()
response = proxy(True)
print("response", response.success, response.message, "within one tick", rospy.get_time() - sent < 0.011)
try:
    proxy(False)
except rospy.ServiceException as e:
    print("handler refused !!", e)
got = []
rospy.Timer(rospy.Duration(0.1), lambda event: got.append(proxy(True).message), oneshot=True)
rospy.sleep(0.5)
print("call in a timer callback returned", got)
server.shutdown()
rospy.sleep(0.1)
try:
    proxy(True)
except rospy.ServiceException as e:
    print("call after shutdown !!", e)
print("end")
