"""Hostile: ask the graph with raw GRAPH frames in an endless loop, past the node library (no sim time charged, no
WAIT ever), reading each answer so that the grader's writes never back up."""
import rospy
import rosgrade_channel as ch
from rosgrade_node import runtime

rospy.init_node("graph_raw_flood")
while True:
    runtime.link.send(ch.encode(ch.GRAPH))
    runtime.link._read(ch.GRAPH_VIEW)
