"""actionlib's ServerGoalHandle and the status the server keeps of each goal (StatusTracker, GoalIDGenerator)."""
from __future__ import annotations

import itertools

import rospy
from actionlib_msgs.msg import GoalID, GoalStatus

_server_goal_count = itertools.count(1)  # one sequence per process, as actionlib's module global


class GoalIDGenerator:
    """Goal ids for goals that came without one: ``<node>-<count>-<secs>.<nsecs>``."""

    def __init__(self, name: str | None = None) -> None:
        self.name = name if name is not None else rospy.get_name()

    def set_name(self, name: str) -> None:
        self.name = name

    def generate_ID(self):  # noqa: N802 - actionlib's name
        now = rospy.Time.now()
        return GoalID(id="%s-%d-%d.%d" % (self.name, next(_server_goal_count), now.secs, now.nsecs), stamp=now)


class StatusTracker:
    """A goal's status on the server (from its goal message, or from a goal id and status alone) and since when no
    handle tracks it (zero while one does); the server forgets it ``status_list_timeout`` after that."""

    def __init__(self, goal_id=None, status=None, goal=None) -> None:
        self.goal = None
        self.handle_tracker = None
        self.status = GoalStatus()
        self.handle_destruction_time = rospy.Time()
        if goal_id is not None:
            self.status.goal_id = goal_id
            self.status.status = status
        else:
            self.goal = goal
            self.status.goal_id = goal.goal_id
            self.status.status = GoalStatus.PENDING
            if self.status.goal_id.id == "":
                self.status.goal_id = GoalIDGenerator().generate_ID()
            if self.status.goal_id.stamp == rospy.Time():
                self.status.goal_id.stamp = rospy.Time.now()


_ACCEPTS = {GoalStatus.PENDING: GoalStatus.ACTIVE, GoalStatus.RECALLING: GoalStatus.PREEMPTING}
_CANCELS = {GoalStatus.PENDING: GoalStatus.RECALLED, GoalStatus.RECALLING: GoalStatus.RECALLED,
            GoalStatus.ACTIVE: GoalStatus.PREEMPTED, GoalStatus.PREEMPTING: GoalStatus.PREEMPTED}
_RUNNING = (GoalStatus.ACTIVE, GoalStatus.PREEMPTING)


class ServerGoalHandle:
    """The server's handle on one goal: accept it, end it (succeeded, aborted, canceled, rejected), send feedback."""

    def __init__(self, status_tracker: StatusTracker | None = None, action_server=None, handle_tracker=None) -> None:
        self.status_tracker = status_tracker
        self.action_server = action_server
        self.handle_tracker = handle_tracker
        self.goal = status_tracker.goal if status_tracker else None

    def _debug_line(self) -> None:
        """actionlib builds a debug line from the goal id (twice) before each transition, at any log level: on a
        handle without a goal each build logs its error."""
        self.get_goal_id()
        self.get_goal_id()

    def get_default_result(self):
        return self.action_server.ActionResultType()

    def _end(self, allowed: dict[int, int], result, text: str, wrong_state: str) -> None:
        """Move to ``allowed[status]`` and publish the result, or log rospy's error for a goal in another state."""
        self._debug_line()
        if not self.goal:
            rospy.logerr("Attempt to set status on an uninitialized ServerGoalHandle")
            return
        with self.action_server.lock:
            status = self.status_tracker.status.status
            if status not in allowed:
                rospy.logerr(wrong_state + ", it is currently in state: %d", status)
                return
            self.status_tracker.status.status = allowed[status]
            self.status_tracker.status.text = text
            self.status_tracker.handle_destruction_time = rospy.Time.now()
            self.action_server.publish_result(self.status_tracker.status, result)

    def set_accepted(self, text: str = "") -> None:
        """PENDING to ACTIVE, or RECALLING to PREEMPTING (a cancel came before the goal was accepted)."""
        self._debug_line()
        if not self.goal:
            rospy.logerr("Attempt to set status on an uninitialized ServerGoalHandle")
            return
        with self.action_server.lock:
            status = self.status_tracker.status.status
            if status not in _ACCEPTS:
                rospy.logerr("To transition to an active state, the goal must be in a pending or recalling state, "
                             "it is currently in state: %d", status)
                return
            self.status_tracker.status.status = _ACCEPTS[status]
            self.status_tracker.status.text = text
            self.action_server.publish_status()

    def set_canceled(self, result=None, text: str = "") -> None:
        self._end(_CANCELS, result or self.get_default_result(), text,
                  "To transition to a cancelled state, the goal must be in a pending, recalling, active, or "
                  "preempting state")

    def set_rejected(self, result=None, text: str = "") -> None:
        self._end({GoalStatus.PENDING: GoalStatus.REJECTED, GoalStatus.RECALLING: GoalStatus.REJECTED},
                  result or self.get_default_result(), text,
                  "To transition to a rejected state, the goal must be in a pending or recalling state")

    def set_aborted(self, result=None, text: str = "") -> None:
        self._end(dict.fromkeys(_RUNNING, GoalStatus.ABORTED), result or self.get_default_result(), text,
                  "To transition to an aborted state, the goal must be in a preempting or active state")

    def set_succeeded(self, result=None, text: str = "") -> None:
        self._end(dict.fromkeys(_RUNNING, GoalStatus.SUCCEEDED), result or self.get_default_result(), text,
                  "To transition to a succeeded state, the goal must be in a preempting or active state")

    def publish_feedback(self, feedback) -> None:
        self._debug_line()
        if not self.goal:
            rospy.logerr("Attempt to publish feedback on an uninitialized ServerGoalHandle")
            return
        with self.action_server.lock:
            self.action_server.publish_feedback(self.status_tracker.status, feedback)

    def get_goal(self):
        return self.goal.goal if self.goal else None

    def get_goal_id(self):
        if not self.goal:
            rospy.logerr("Attempt to get a goal id on an uninitialized ServerGoalHandle")
            return GoalID()
        with self.action_server.lock:
            return self.status_tracker.status.goal_id

    def get_goal_status(self):
        if not self.goal:
            rospy.logerr("Attempt to get goal status on an uninitialized ServerGoalHandle")
            return GoalStatus()
        with self.action_server.lock:
            return self.status_tracker.status

    def __eq__(self, other) -> bool:
        if not self.goal or not other.goal:
            return False
        return self.get_goal_id().id == other.get_goal_id().id

    def __ne__(self, other) -> bool:
        return not self.__eq__(other)

    def __hash__(self) -> int:
        return hash(self.get_goal_id().id)

    def set_cancel_requested(self) -> bool:
        """PENDING to RECALLING or ACTIVE to PREEMPTING; True when the server's cancel callback should run."""
        self._debug_line()
        if not self.goal:
            return False
        with self.action_server.lock:
            following = {GoalStatus.PENDING: GoalStatus.RECALLING, GoalStatus.ACTIVE: GoalStatus.PREEMPTING}
            status = self.status_tracker.status.status
            if status not in following:
                return False
            self.status_tracker.status.status = following[status]
            self.action_server.publish_status()
            return True
