#!/usr/bin/env python3
# actionlib's Test action served on /count (counts to the goal, a feedback every 0.1 s, preemptible), and what its
# clients send on /count/goal and /count/cancel as it arrives: the goal id's form, its stamps, the cancel's id.
import re

import actionlib
import rospy
from actionlib.msg import TestAction, TestFeedback, TestResult
from actionlib.msg import TestActionGoal
from actionlib_msgs.msg import GoalID

ids = []


def heard_goal(msg):
    stamp = msg.goal_id.stamp
    match = re.fullmatch(r"(/[\w/]+)-(\d+)-(\d+)\.(\d+)", msg.goal_id.id)
    ids.append(msg.goal_id.id)
    print("goal", match.group(1), "count", match.group(2), "decimals", len(match.group(4)), "id time is its stamp",
          "%s.%s" % (match.group(3), match.group(4)) == "%.3f" % stamp.to_sec(),
          "header stamp is its stamp", msg.header.stamp == stamp, "goal", msg.goal.goal, flush=True)


def heard_cancel(msg):
    print("cancel of goal", ids.index(msg.id) + 1 if msg.id in ids else msg.id, "stamp zero", msg.stamp.is_zero(),
          flush=True)


def execute(goal):
    for n in range(goal.goal):
        if server.is_preempt_requested():
            server.set_preempted(TestResult(n))
            return
        server.publish_feedback(TestFeedback(n))
        rospy.sleep(0.1)
    server.set_succeeded(TestResult(goal.goal))


rospy.init_node("count_server")
rospy.Subscriber("/count/goal", TestActionGoal, heard_goal)
rospy.Subscriber("/count/cancel", GoalID, heard_cancel)
server = actionlib.SimpleActionServer("/count", TestAction, execute_cb=execute, auto_start=False)
server.start()
rospy.spin()
