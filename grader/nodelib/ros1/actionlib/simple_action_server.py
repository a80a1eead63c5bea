"""actionlib's SimpleActionServer: one goal at a time (a newer goal preempts the current one), run by an execute
callback in a thread of its own or driven by goal and preempt callbacks."""
from __future__ import annotations

import threading
import traceback

import rospy
from actionlib_msgs.msg import GoalStatus

from .action_server import ActionServer
from .server_goal_handle import ServerGoalHandle

_REPLACED = "This goal was canceled because another goal was received by the simple action server"


class SimpleActionServer:
    """Accepts the newest goal; ``execute_cb(goal)`` runs each accepted goal in the server's own thread."""

    def __init__(self, name: str, ActionSpec: type, execute_cb=None, auto_start: bool = True) -> None:
        self.new_goal = False
        self.preempt_request = False
        self.new_goal_preempt_request = False
        self.execute_callback = execute_cb
        self.goal_callback = None
        self.preempt_callback = None
        self.need_to_terminate = False
        self.terminate_mutex = threading.RLock()
        self.lock = threading.RLock()
        self.execute_condition = threading.Condition(self.lock)
        self.current_goal = ServerGoalHandle()
        self.next_goal = ServerGoalHandle()
        if self.execute_callback:
            self.execute_thread = threading.Thread(None, self.executeLoop)
            self.execute_thread.start()
        else:
            self.execute_thread = None
        self.action_server = ActionServer(name, ActionSpec, self.internal_goal_callback,
                                          self.internal_preempt_callback, auto_start)

    def accept_new_goal(self):
        """Make the waiting goal current (canceling the one it replaces) and return its goal message."""
        with self.action_server.lock, self.lock:
            if not self.new_goal or not self.next_goal.get_goal():
                rospy.logerr("Attempting to accept the next goal when a new goal is not available")
                return None
            if self.is_active() and self.current_goal.get_goal() and self.current_goal != self.next_goal:
                self.current_goal.set_canceled(None, _REPLACED)
            self.current_goal = self.next_goal
            self.new_goal = False
            self.preempt_request = self.new_goal_preempt_request
            self.new_goal_preempt_request = False
            self.current_goal.set_accepted("This goal has been accepted by the simple action server")
            return self.current_goal.get_goal()

    def is_new_goal_available(self) -> bool:
        return self.new_goal

    def is_preempt_requested(self) -> bool:
        return self.preempt_request

    def is_active(self) -> bool:
        if not self.current_goal.get_goal():
            return False
        return self.current_goal.get_goal_status().status in (GoalStatus.ACTIVE, GoalStatus.PREEMPTING)

    def set_succeeded(self, result=None, text: str = "") -> None:
        with self.action_server.lock, self.lock:
            self.current_goal.set_succeeded(result or self.get_default_result(), text)

    def set_aborted(self, result=None, text: str = "") -> None:
        with self.action_server.lock, self.lock:
            self.current_goal.set_aborted(result or self.get_default_result(), text)

    def set_preempted(self, result=None, text: str = "") -> None:
        result = result or self.get_default_result()
        with self.action_server.lock, self.lock:
            self.current_goal.set_canceled(result, text)

    def publish_feedback(self, feedback) -> None:
        self.current_goal.publish_feedback(feedback)

    def get_default_result(self):
        return self.action_server.ActionResultType()

    def register_goal_callback(self, cb) -> None:
        if self.execute_callback:
            rospy.logwarn("Cannot call SimpleActionServer.register_goal_callback() because an executeCallback "
                          "exists. Not going to register it.")
        else:
            self.goal_callback = cb

    def register_preempt_callback(self, cb) -> None:
        self.preempt_callback = cb

    def start(self) -> None:
        self.action_server.start()

    def _newer_than_held(self, goal) -> bool:
        stamp = goal.get_goal_id().stamp
        return all(not held.get_goal() or stamp >= held.get_goal_id().stamp
                   for held in (self.current_goal, self.next_goal))

    def internal_goal_callback(self, goal) -> None:
        """A goal no older than the current and the waiting one becomes the next goal (preempting the current one);
        an older one is canceled."""
        with self.execute_condition:
            try:
                if not self._newer_than_held(goal):
                    goal.set_canceled(None, _REPLACED)
                    return
                if self.next_goal.get_goal() and (not self.current_goal.get_goal()
                                                  or self.next_goal != self.current_goal):
                    self.next_goal.set_canceled(None, _REPLACED)
                self.next_goal = goal
                self.new_goal = True
                self.new_goal_preempt_request = False
                if self.is_active():
                    self.preempt_request = True
                    if self.preempt_callback:
                        self.preempt_callback()
                if self.goal_callback:
                    self.goal_callback()
                self.execute_condition.notify()
            except Exception as exc:  # noqa: BLE001 - actionlib logs it and goes on
                rospy.logerr("SimpleActionServer.internal_goal_callback - exception %s", str(exc))

    def internal_preempt_callback(self, preempt) -> None:
        with self.lock:
            if preempt == self.current_goal:
                self.preempt_request = True
                if self.preempt_callback:
                    self.preempt_callback()
            elif preempt == self.next_goal:
                self.new_goal_preempt_request = True

    def executeLoop(self) -> None:  # noqa: N802 - actionlib's name
        """Run each new goal through the execute callback; a goal it leaves running is aborted."""
        while not rospy.is_shutdown():
            with self.terminate_mutex:
                if self.need_to_terminate:
                    break
            if self.is_active():
                rospy.logerr("Should never reach this code with an active goal")
                return
            if self.is_new_goal_available():
                goal = self.accept_new_goal()
                try:
                    self.execute_callback(goal)
                    if self.is_active():
                        rospy.logwarn("Your executeCallback did not set the goal to a terminal status.  This is a "
                                      "bug in your ActionServer implementation. Fix your code!  For now, the "
                                      "ActionServer will set this goal to aborted")
                        self.set_aborted(None, "No terminal state was set.")
                except Exception as exc:  # noqa: BLE001 - a student's callback: logged, the goal aborted
                    rospy.logerr("Exception in your execute callback: %s\n%s", str(exc), traceback.format_exc())
                    self.set_aborted(None, "Exception in execute callback: %s" % str(exc))
            with self.execute_condition:
                self.execute_condition.wait(0.1)
