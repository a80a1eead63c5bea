#!/usr/bin/env python3
"""The actionlib tutorial's execute-callback server in rospy without its preempt check: node fibonacci serves the
Fibonacci action on /fibonacci, adds one number a second, publishing the sequence so far as feedback, and succeeds
with order + 1 numbers; it never asks whether the goal was preempted, so a cancelled goal runs on."""
import actionlib
import rospy
from actionlib_tutorials.msg import FibonacciAction, FibonacciFeedback, FibonacciResult


class FibonacciServer:

    def __init__(self, name):
        self.name = name
        self.server = actionlib.SimpleActionServer(name, FibonacciAction, execute_cb=self.execute, auto_start=False)
        self.server.start()

    def execute(self, goal):
        step = rospy.Rate(1)
        feedback = FibonacciFeedback(sequence=[0, 1])
        rospy.loginfo("%s: Executing, creating fibonacci sequence of order %i", self.name, goal.order)
        for i in range(1, goal.order):
            feedback.sequence.append(feedback.sequence[i] + feedback.sequence[i - 1])
            self.server.publish_feedback(feedback)
            step.sleep()
        rospy.loginfo("%s: Succeeded", self.name)
        self.server.set_succeeded(FibonacciResult(sequence=feedback.sequence))


if __name__ == "__main__":
    rospy.init_node("fibonacci")
    FibonacciServer(rospy.get_name())
    rospy.spin()
