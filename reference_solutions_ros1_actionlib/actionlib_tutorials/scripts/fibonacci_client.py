#!/usr/bin/env python3
"""The actionlib tutorial's Fibonacci client in rospy: waits for /fibonacci, sends order 20, prints each feedback and
the result."""
import actionlib
import rospy
from actionlib_tutorials.msg import FibonacciAction, FibonacciGoal


def on_feedback(feedback):
    print("Feedback:", list(feedback.sequence), flush=True)


if __name__ == "__main__":
    rospy.init_node("fibonacci_client")
    client = actionlib.SimpleActionClient("fibonacci", FibonacciAction)
    client.wait_for_server()
    client.send_goal(FibonacciGoal(order=20), feedback_cb=on_feedback)
    client.wait_for_result()
    print("Result:", ", ".join(str(n) for n in client.get_result().sequence), flush=True)
