#!/usr/bin/env python3
"""Probe 35 (issue 28): actionlib between a SimpleActionServer and a SimpleActionClient of one node (actionlib's own
Test action: goal n counts to n with a feedback every 0.1 s). wait_for_server before the server times out; a goal
runs with its active, feedback and done callbacks; a cancel while it runs ends PREEMPTED with the result set then; a
second goal sent while one runs preempts it; an execute callback that sets no terminal state, or raises, aborts the
goal with actionlib's words; the status topic lists the goals with their final statuses."""
import actionlib
import rospy
from actionlib.msg import TestAction, TestFeedback, TestGoal, TestResult
from actionlib_msgs.msg import GoalStatus, GoalStatusArray

rospy.init_node("p35_actionlib")
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)


def t():
    return "t=%.3f" % (rospy.get_time() - T0)


client = actionlib.SimpleActionClient("/p35_count", TestAction)
print("wait_for_server before the server", client.wait_for_server(rospy.Duration(0.3)), t())
print("state with no goal", client.get_state(), GoalStatus.to_string(client.get_state()))


def execute(goal):
    print("execute", goal.goal, "new goal available", server.is_new_goal_available())
    if goal.goal == -1:
        return
    if goal.goal == -2:
        raise ValueError("no negative goals")
    for i in range(1, goal.goal + 1):
        if server.is_preempt_requested():
            print("preempt requested at", i)
            server.set_preempted(TestResult(result=-i), "stopped")
            return
        server.publish_feedback(TestFeedback(feedback=i))
        rospy.sleep(0.1)
    server.set_succeeded(TestResult(result=goal.goal * 10), "counted")


server = actionlib.SimpleActionServer("/p35_count", TestAction, execute_cb=execute, auto_start=False)
server.start()
print("wait_for_server once started", client.wait_for_server(rospy.Duration(2.0)))

events = []


def run(goal, cancel_after=None):
    del events[:]
    client.send_goal(TestGoal(goal=goal), done_cb=lambda state, result: events.append(
                         ("done", GoalStatus.to_string(state), result.result if result else None)),
                     active_cb=lambda: events.append(("active",)),
                     feedback_cb=lambda fb: events.append(("feedback", fb.feedback)))
    if cancel_after is not None:
        rospy.sleep(cancel_after)
        client.cancel_goal()
    finished = client.wait_for_result(rospy.Duration(3.0))
    print("goal", goal, "finished", finished, "state", GoalStatus.to_string(client.get_state()),
          "text", repr(client.get_goal_status_text()), "result", client.get_result().result)
    print("  callbacks", events)


run(3)
run(10, cancel_after=0.25)
run(-1)
run(-2)
client.send_goal(TestGoal(goal=10))
rospy.sleep(0.25)
first = client.gh
run(2)
print("first goal ended", GoalStatus.to_string(first.get_goal_status()), repr(first.get_goal_status_text()))
rospy.sleep(0.25)  # the last status reaches the client's connection (under real rospy it may lag the result)
status = rospy.wait_for_message("/p35_count/status", GoalStatusArray, timeout=1.0)
print("status list", [(GoalStatus.to_string(s.status), s.text) for s in status.status_list])
print("wait_for_result with no goal", actionlib.SimpleActionClient("/p35_other", TestAction).wait_for_result())
print("end")
rospy.signal_shutdown("done")
