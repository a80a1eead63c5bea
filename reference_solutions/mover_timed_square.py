#!/usr/bin/env python3
"""Reference for mover_timed_square (seed 001, Task 5a): a time-based square, repeated until Ctrl+C.

The course calls this script mover.py; the rubric looks for mover_timed_square.py, then mover.py.
"""

import math

import rospy
from geometry_msgs.msg import Twist

FORWARD_SPEED = 0.2  # m/s
FORWARD_TIME = 5.0  # s: 1 m sides
TURN_SPEED = 0.5  # rad/s
TURN_TIME = (math.pi / 2) / TURN_SPEED  # s: a quarter turn


def mover():
    pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
    rospy.init_node('mover', anonymous=True)
    rospy.on_shutdown(lambda: pub.publish(Twist()))  # stop the robot on Ctrl+C
    rate = rospy.Rate(10)  # 10hz

    forward = Twist()
    forward.linear.x = FORWARD_SPEED
    turn = Twist()
    turn.angular.z = TURN_SPEED

    # Under simulated time the clock reads 0 until the first /clock message arrives after init_node.
    while rospy.Time.now().is_zero() and not rospy.is_shutdown():
        rate.sleep()

    moving_forward = True
    phase_start = rospy.Time.now().to_sec()
    while not rospy.is_shutdown():
        elapsed = rospy.Time.now().to_sec() - phase_start
        if moving_forward and elapsed >= FORWARD_TIME:
            moving_forward, phase_start = False, phase_start + FORWARD_TIME
        elif not moving_forward and elapsed >= TURN_TIME:
            moving_forward, phase_start = True, phase_start + TURN_TIME
        pub.publish(forward if moving_forward else turn)
        rate.sleep()


if __name__ == '__main__':
    try:
        mover()
    except rospy.ROSInterruptException:
        pass
