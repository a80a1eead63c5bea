#!/usr/bin/env python3
"""Subscribes hundreds of times to the odometry and then stops reading its end of the channel (but says it waits)."""
import os

import rospy
import rosgrade_channel as ch
from nav_msgs.msg import Odometry
from rosgrade_node import runtime

rospy.init_node("stop_reading")
for ident in range(10_000, 10_500):
    runtime.link.send_json(ch.SUBSCRIBE, {"id": ident, "topic": "/odom", "type": "nav_msgs/Odometry",
                                          "md5sum": Odometry._md5sum, "queue_size": 1, "latch": False})
runtime.link.send_json(ch.WAIT, {"wake_ns": None})
never, _ = os.pipe()
os.read(never, 1)  # blocks for good without reading the grader's batches: the channel's pipe fills up
