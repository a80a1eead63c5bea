#!/usr/bin/env python3
"""The rospy service tutorial's server: add_two_ints_server offers add_two_ints (the package's own AddTwoInts) and
answers each request with the sum of its two numbers."""
import rospy
from beginner_tutorials.srv import AddTwoInts, AddTwoIntsResponse


def add(request):
    total = request.a + request.b
    print(f"Returning [{request.a} + {request.b} = {total}]")
    return AddTwoIntsResponse(total)


if __name__ == "__main__":
    rospy.init_node("add_two_ints_server")
    rospy.Service("add_two_ints", AddTwoInts, add)
    print("Ready to add two ints.")
    rospy.spin()
