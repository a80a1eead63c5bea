"""Hostile: a GRAPH query carrying bytes the protocol does not define (a forged frame, past the node library)."""
import rospy
import rosgrade_channel as ch
from rosgrade_node import runtime

rospy.init_node("graph_payload")
runtime.link.send(ch.encode(ch.GRAPH, b"x" * 1000))
rospy.sleep(1.0)
