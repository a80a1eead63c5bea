#!/usr/bin/env python3
"""Sends one malformed frame, chosen by argv[1], straight onto the grader's channel after a normal start."""
import json
import sys

import rospy
import rosgrade_channel as ch
from rosgrade_node import runtime

ATTACKS = {
    # 100k nested JSON arrays: a recursive parser runs out of stack
    "nested_json": (ch.LOG, b"[" * 100_000 + b"]" * 100_000),
    "log_line_not_a_number": (ch.LOG, json.dumps({"level": 2, "msg": "hi", "name": "/bad_frame", "file": "f.py",
                                                   "function": "f", "line": "forty-two"}).encode()),
    "exception_frames_not_a_list": (ch.EXCEPTION, json.dumps({"type": "E", "message": "m", "frames": 7,
                                                              "where": "uncaught"}).encode()),
    "exception_frame_fields": (ch.EXCEPTION, json.dumps(
        {"type": "E", "message": "m", "where": "uncaught",
         "frames": [{"file": ["x"], "line": {"a": 1}, "function": "f", "text": ""}]}).encode()),
    "unknown_kind": (99, b"{}"),
    "oversize_json": (ch.LOG, json.dumps({"level": 2, "msg": "x" * 400_000}).encode()),
    "advertise_bad_fields": (ch.ADVERTISE, json.dumps(
        {"id": 7, "topic": "/chatter", "type": "std_msgs/String", "md5sum": "992ce8a1687cec8c8bd883ec73ca41d1",
         "queue_size": "ten", "latch": "yes please"}).encode()),
    "wait_float": (ch.WAIT, json.dumps({"wake_ns": 1.5e18}).encode()),
    "output_bad_stream": (ch.OUTPUT, b"\x07hello"),
}

rospy.init_node("bad_frame")
rospy.sleep(0.5)
kind, payload = ATTACKS[sys.argv[1] if len(sys.argv) > 1 else "nested_json"]
runtime.link.send(ch.encode(kind, payload))
rospy.sleep(2.0)
