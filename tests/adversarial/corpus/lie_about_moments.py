#!/usr/bin/env python3
"""Breaks the moments contract from an /odom callback, as chosen by argv[1]: raw frames straight onto the channel,
past the node library (which would have said which moment it was at first)."""
import sys

import rospy
import rosgrade_channel as ch
from nav_msgs.msg import Odometry
from rosgrade_node import runtime


def attack(name: str) -> bytes:
    now = runtime.scheduler.world_ns  # the moment the callback runs at, not named to the grader yet
    return {
        "no_moment": ch.encode(ch.OUTPUT, b"\x01hello\n"),  # a frame before any MOMENT
        "moment_out_of_range": ch.encode_moment(2 ** 62) + ch.encode_wait(None),
        "moment_twice": ch.encode_moment(now) + ch.encode_moment(now) + ch.encode_wait(None),
    }[name]


seen = [0]


def callback(msg):
    seen[0] += 1
    if seen[0] == 10:
        ch.write_all(runtime.link._wfd, attack(sys.argv[1]))


rospy.init_node("lie_about_moments")
rospy.Subscriber("/odom", Odometry, callback)
rate = rospy.Rate(2)
while not rospy.is_shutdown():
    rate.sleep()
