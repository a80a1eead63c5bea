"""actionlib's SimpleActionClient: one goal at a time, with done/active/feedback callbacks and a blocking wait."""
from __future__ import annotations

import threading

import rospy
from actionlib_msgs.msg import GoalStatus

from ._spec import name_of_constant
from .action_client import ActionClient, CommState


class SimpleGoalState:
    """The three states a simple client's goal goes through."""

    PENDING = 0
    ACTIVE = 1
    DONE = 2


SimpleGoalState.to_string = classmethod(name_of_constant)


class SimpleActionClient:
    """Tracks the last goal sent; a new goal forgets the previous one (its callbacks stop)."""

    def __init__(self, ns: str, ActionSpec: type) -> None:
        self.action_client = ActionClient(ns, ActionSpec)
        self.simple_state = SimpleGoalState.DONE
        self.gh = None
        self.done_condition = threading.Condition()
        self.done_cb = self.active_cb = self.feedback_cb = None

    def wait_for_server(self, timeout=rospy.Duration()) -> bool:
        return self.action_client.wait_for_server(timeout)

    def send_goal(self, goal, done_cb=None, active_cb=None, feedback_cb=None) -> None:
        """Send ``goal``: done_cb(state, result) once it ends, active_cb() once it runs, feedback_cb(feedback)."""
        self.stop_tracking_goal()
        self.done_cb, self.active_cb, self.feedback_cb = done_cb, active_cb, feedback_cb
        self.simple_state = SimpleGoalState.PENDING
        self.gh = self.action_client.send_goal(goal, self._handle_transition, self._handle_feedback)

    def send_goal_and_wait(self, goal, execute_timeout=rospy.Duration(), preempt_timeout=rospy.Duration()) -> int:
        """Send, wait; past ``execute_timeout`` cancel and wait ``preempt_timeout`` more; the state it ended in."""
        self.send_goal(goal)
        if not self.wait_for_result(execute_timeout):
            self.cancel_goal()
            self.wait_for_result(preempt_timeout)
        return self.get_state()

    def wait_for_result(self, timeout=rospy.Duration()) -> bool:
        """Block until the goal is done (a zero timeout: for ever), waking every 0.1 s of ROS time to look."""
        if not self.gh:
            rospy.logerr("Called wait_for_result when no goal exists")
            return False
        deadline = rospy.get_rostime() + timeout
        period = rospy.Duration(0.1)
        with self.done_condition:
            while not rospy.is_shutdown():
                left = deadline - rospy.get_rostime()
                if timeout > rospy.Duration(0.0) and left <= rospy.Duration(0.0):
                    break
                if self.simple_state == SimpleGoalState.DONE:
                    break
                if left > period or timeout == rospy.Duration():
                    left = period
                self.done_condition.wait(left.to_sec())
        return self.simple_state == SimpleGoalState.DONE

    def get_result(self):
        if not self.gh:
            rospy.logerr("Called get_result when no goal is running")
            return None
        return self.gh.get_result()

    def get_state(self) -> int:
        """The goal's status as a simple client reports it (RECALLING as PENDING, PREEMPTING as ACTIVE)."""
        if not self.gh:
            return GoalStatus.LOST
        status = self.gh.get_goal_status()
        return {GoalStatus.RECALLING: GoalStatus.PENDING, GoalStatus.PREEMPTING: GoalStatus.ACTIVE}.get(status, status)

    def get_goal_status_text(self) -> str:
        if not self.gh:
            rospy.logerr("Called get_goal_status_text when no goal is running")
            return "ERROR: Called get_goal_status_text when no goal is running"
        return self.gh.get_goal_status_text()

    def cancel_all_goals(self) -> None:
        self.action_client.cancel_all_goals()

    def cancel_goals_at_and_before_time(self, time) -> None:
        self.action_client.cancel_goals_at_and_before_time(time)

    def cancel_goal(self) -> None:
        if self.gh:
            self.gh.cancel()

    def stop_tracking_goal(self) -> None:
        self.gh = None

    def _set_simple_state(self, state: int) -> None:
        self.simple_state = state

    def _handle_transition(self, gh) -> None:
        if gh != self.gh:
            rospy.logerr("Got a transition callback on a goal handle that we're not tracking")
            return
        comm_state = gh.get_comm_state()
        if comm_state in (CommState.ACTIVE, CommState.PREEMPTING):
            if self.simple_state == SimpleGoalState.PENDING:
                self._set_simple_state(SimpleGoalState.ACTIVE)
                if self.active_cb:
                    self.active_cb()
            elif self.simple_state == SimpleGoalState.DONE:
                rospy.logerr(self._unexpected(comm_state))
        elif comm_state == CommState.RECALLING:
            if self.simple_state != SimpleGoalState.PENDING:
                rospy.logerr(self._unexpected(comm_state))
        elif comm_state == CommState.DONE:
            if self.simple_state == SimpleGoalState.DONE:
                rospy.logerr("SimpleActionClient received DONE twice")
                return
            if self.done_cb:
                self.done_cb(gh.get_goal_status(), gh.get_result())
            with self.done_condition:
                self._set_simple_state(SimpleGoalState.DONE)
                self.done_condition.notify_all()

    def _unexpected(self, comm_state: int) -> str:
        return "Received comm state %s when in simple state %s with SimpleActionClient in NS %s" % (
            CommState.to_string(comm_state), SimpleGoalState.to_string(self.simple_state),
            rospy.resolve_name(self.action_client.ns))

    def _handle_feedback(self, gh, feedback) -> None:
        if not self.gh:
            return
        if gh != self.gh:
            rospy.logerr("Got a feedback callback on a goal handle that we're not tracking. %s vs %s" % (
                self.gh.comm_state_machine.action_goal.goal_id.id, gh.comm_state_machine.action_goal.goal_id.id))
            return
        if self.feedback_cb:
            self.feedback_cb(feedback)
