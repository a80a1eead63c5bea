#!/usr/bin/env python3
"""The actionlib tutorial's Fibonacci server in rospy: a SimpleActionServer on /fibonacci that publishes the sequence
so far as feedback at 10 Hz, honours a preempt and succeeds with order + 1 numbers."""
import actionlib
import rospy
from actionlib_tutorials.msg import FibonacciAction, FibonacciFeedback, FibonacciResult


class FibonacciServer:

    def __init__(self, name):
        self.server = actionlib.SimpleActionServer(name, FibonacciAction, execute_cb=self.execute, auto_start=False)
        self.server.start()

    def execute(self, goal):
        rate = rospy.Rate(10)
        sequence = [0, 1]
        rospy.loginfo("Executing, creating fibonacci sequence of order %i", goal.order)
        for i in range(1, goal.order):
            if self.server.is_preempt_requested() or rospy.is_shutdown():
                rospy.loginfo("Preempted")
                self.server.set_preempted()
                return
            sequence.append(sequence[i] + sequence[i - 1])
            self.server.publish_feedback(FibonacciFeedback(sequence=sequence))
            rate.sleep()
        rospy.loginfo("Succeeded")
        self.server.set_succeeded(FibonacciResult(sequence=sequence))


if __name__ == "__main__":
    rospy.init_node("fibonacci")
    FibonacciServer(rospy.get_name())
    rospy.spin()
