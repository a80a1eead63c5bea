#!/usr/bin/env python3
"""Probe 36 (issue 28): actionlib's ActionServer and ActionClient (not the simple ones) in one node, with the Test
action: the comm states a client's goal walks through when the server accepts and succeeds it, rejects it, or is
asked to cancel it while pending (RECALLED) and while active (PREEMPTED); a cancel for a goal that comes before the
goal (the goal is then RECALLED at once); cancel_all_goals; get_terminal_state; and the server forgetting ended goals
status_list_timeout after they ended; and the errors actionlib logs for a cancel reaching a status it keeps without
a goal."""
import actionlib
import rospy
from actionlib import CommState
from actionlib.msg import TestAction, TestGoal, TestResult
from actionlib_msgs.msg import GoalID, GoalStatus

rospy.init_node("p36_actionlib_handles")
rospy.set_param("/p36/status_list_timeout", 1.0)
rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
held = {}


def on_goal(handle):
    n = handle.get_goal().goal
    print("server got goal", n, "status", GoalStatus.to_string(handle.get_goal_status().status))
    if n == 1:
        handle.set_accepted("ok")
        handle.set_succeeded(TestResult(result=10), "done")
    elif n == 2:
        handle.set_rejected(TestResult(result=20), "no")
    else:
        held[n] = handle  # left pending (3) or accepted (4, 5) until canceled
        if n in (4, 5):
            handle.set_accepted("running")


def on_cancel(handle):
    n = handle.get_goal().goal
    print("server cancel for goal", n, "status", GoalStatus.to_string(handle.get_goal_status().status))
    handle.set_canceled(TestResult(result=-n), "canceled")


server = actionlib.ActionServer("/p36", TestAction, on_goal, on_cancel, auto_start=False)
server.start()
client = actionlib.ActionClient("/p36", TestAction)
print("wait_for_server", client.wait_for_server(rospy.Duration(2.0)))
seen = {}


def track(n):
    def on_transition(gh):
        seen.setdefault(n, []).append(CommState.to_string(gh.get_comm_state()))
    return on_transition


handles = {n: client.send_goal(TestGoal(goal=n), track(n)) for n in (1, 2, 3, 4)}
rospy.sleep(0.5)
handles[3].cancel()
handles[4].cancel()
rospy.sleep(0.5)
for n, gh in sorted(handles.items()):
    result = gh.get_result()
    print("goal", n, "transitions", seen.get(n), "terminal", GoalStatus.to_string(gh.get_terminal_state()),
          "text", repr(gh.get_goal_status_text()), "result", None if result is None else result.result)
early = GoalID(id="p36-early", stamp=rospy.Time(0))
client.pub_cancel.publish(early)
rospy.sleep(0.3)
goal = client.manager.ActionGoal(goal_id=GoalID(id="p36-early", stamp=rospy.Time(0)), goal=TestGoal(goal=9))
client.pub_goal.publish(goal)
rospy.sleep(0.7)  # 3 and 4 ended 1.5 s ago and are forgotten; the early goal is kept until 1 s after it came
print("statuses", sorted((s.goal_id.id.split("-")[-2] if s.goal_id.id != "p36-early" else s.goal_id.id,
                          GoalStatus.to_string(s.status)) for s in client.last_status_msg.status_list))
five = client.send_goal(TestGoal(goal=5), track(5))
rospy.sleep(0.3)
client.cancel_all_goals()
rospy.sleep(0.3)
print("goal 5 transitions", seen.get(5), "terminal", GoalStatus.to_string(five.get_terminal_state()))
rospy.sleep(1.5)
print("statuses after the timeout", len(client.last_status_msg.status_list))
print("end")
rospy.signal_shutdown("done")
