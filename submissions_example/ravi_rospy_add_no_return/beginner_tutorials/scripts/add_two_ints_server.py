#!/usr/bin/env python3
"""The rospy service tutorial's server with the classic slip: the handler prints the sum but never returns a
response, so rospy answers every call with an error."""
import rospy
from beginner_tutorials.srv import AddTwoInts


def add(request):
    print(f"Returning [{request.a} + {request.b} = {request.a + request.b}]")


if __name__ == "__main__":
    rospy.init_node("add_two_ints_server")
    rospy.Service("add_two_ints", AddTwoInts, add)
    print("Ready to add two ints.")
    rospy.spin()
