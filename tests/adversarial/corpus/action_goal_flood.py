#!/usr/bin/env python3
"""A rospy node with an actionlib ActionServer that accepts every goal and never ends one, and an ActionClient in
the same node sending goals to it without end: the server's status list (every goal, on each status message) grows."""
import actionlib
import rospy
from actionlib.msg import TestAction, TestGoal

rospy.init_node("goal_flood")
server = actionlib.ActionServer("/flood", TestAction, lambda handle: handle.set_accepted(), auto_start=False)
server.start()
client = actionlib.ActionClient("/flood", TestAction)
client.wait_for_server(rospy.Duration(2.0))
handles = []
while not rospy.is_shutdown():
    handles.append(client.send_goal(TestGoal(goal=len(handles))))
    if len(handles) % 100 == 0:
        print("goals", len(handles), flush=True)
