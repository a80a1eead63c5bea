#!/usr/bin/env python3
"""Offers a service, then sends an answer to a request it was never given, straight onto the channel."""
import rosgrade_channel as ch
import rospy
from rosgrade_node import runtime
from std_srvs.srv import Trigger

rospy.init_node("forged_answer")
server = rospy.Service("/forged", Trigger, lambda request: (True, "ok"))
runtime.link.send(ch.encode_header_bytes(ch.RESPOND, {"id": server._handle, "seq": 99, "status": "ok", "error": ""},
                                         b"\x01\x00\x00\x00\x00"))
rospy.sleep(1.0)
