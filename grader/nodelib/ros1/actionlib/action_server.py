"""actionlib's ActionServer: goals in on ``<ns>/goal`` and ``<ns>/cancel``, every goal's status out on ``<ns>/status``
(latched, on a timer and at each change), results and feedback out, as python3-actionlib 1.14 serves them."""
from __future__ import annotations

import threading

import rospy
from actionlib_msgs.msg import GoalID, GoalStatus, GoalStatusArray

from ._spec import ActionTypes
from .server_goal_handle import GoalIDGenerator, ServerGoalHandle, StatusTracker


def nop_cb(goal_handle) -> None:
    """The default cancel callback: nothing."""


class _HandleTracker:
    """Stands for a goal's handles being alive (actionlib's HandleTrackerDeleter)."""

    def __init__(self, action_server, status_tracker: StatusTracker) -> None:
        self.action_server = action_server
        self.status_tracker = status_tracker


class ActionServer:
    """Many goals at once: each new goal goes to ``goal_cb`` as a ServerGoalHandle, each cancel to ``cancel_cb``."""

    def __init__(self, ns: str, ActionSpec: type, goal_cb, cancel_cb=nop_cb, auto_start: bool = True) -> None:
        self.ns = ns
        types = ActionTypes(ActionSpec)
        self.ActionSpec, self.ActionGoal, self.ActionResult = types.ActionSpec, types.ActionGoal, types.ActionResult
        self.ActionResultType, self.ActionFeedback = types.ActionResultType, types.ActionFeedback
        self.goal_sub = self.cancel_sub = self.status_pub = self.result_pub = self.feedback_pub = None
        self.lock = threading.RLock()
        self.status_timer = None
        self.status_list: list[StatusTracker] = []
        self.last_cancel = rospy.Time()
        self.status_list_timeout = rospy.Duration()
        self.id_generator = GoalIDGenerator()
        self.goal_callback = goal_cb
        assert self.goal_callback
        self.cancel_callback = cancel_cb
        self.auto_start = auto_start
        self.started = False
        if self.auto_start:
            rospy.logwarn("You've passed in true for auto_start to the python action server, you should always pass "
                          "in false to avoid race conditions.")
            self.start()

    def register_goal_callback(self, cb) -> None:
        self.goal_callback = cb

    def register_cancel_callback(self, cancel_cb) -> None:
        self.cancel_callback = cancel_cb

    def start(self) -> None:
        with self.lock:
            self.initialize()
            self.started = True
            self.publish_status()

    def stop(self) -> None:
        with self.lock:
            self.started = False
            if self.status_timer is not None:
                self.status_timer.shutdown()
            for endpoint in (self.goal_sub, self.cancel_sub, self.status_pub, self.feedback_pub, self.result_pub):
                endpoint.unregister()

    @staticmethod
    def _queue_size(name: str, default, negative):
        size = rospy.get_param(name, default)
        return negative if size < 0 else size

    def _status_frequency(self, base: str) -> float:
        """``<ns>/status_frequency`` (deprecated, with a warning), else the nearest ``actionlib_status_frequency``."""
        if rospy.has_param(base + "/status_frequency"):
            frequency = rospy.get_param(base + "/status_frequency", 5.0)
            rospy.logwarn("You're using the deprecated status_frequency parameter, please switch to "
                          "actionlib_status_frequency.")
            return frequency
        found = rospy.search_param("actionlib_status_frequency")
        return 5.0 if found is None else rospy.get_param(found, 5.0)

    def initialize(self) -> None:
        """Advertise and subscribe the action's five topics; start the status timer."""
        base = rospy.remap_name(self.ns)
        self.pub_queue_size = self._queue_size("actionlib_server_pub_queue_size", 50, 50)
        self.status_pub = rospy.Publisher(base + "/status", GoalStatusArray, latch=True,
                                          queue_size=self.pub_queue_size)
        self.result_pub = rospy.Publisher(base + "/result", self.ActionResult, queue_size=self.pub_queue_size)
        self.feedback_pub = rospy.Publisher(base + "/feedback", self.ActionFeedback, queue_size=self.pub_queue_size)
        self.sub_queue_size = self._queue_size("actionlib_server_sub_queue_size", -1, None)
        self.goal_sub = rospy.Subscriber(base + "/goal", self.ActionGoal, callback=self.internal_goal_callback,
                                         queue_size=self.sub_queue_size)
        self.cancel_sub = rospy.Subscriber(base + "/cancel", GoalID, callback=self.internal_cancel_callback,
                                           queue_size=self.sub_queue_size)
        self.status_frequency = self._status_frequency(base)
        self.status_list_timeout = rospy.Duration(rospy.get_param(base + "/status_list_timeout", 5.0))
        if self.status_frequency > 0.0:
            self.status_timer = rospy.Timer(rospy.Duration(1.0 / self.status_frequency), self.publish_status_async)

    def publish_result(self, status, result) -> None:
        with self.lock:
            message = self.ActionResult()
            message.header.stamp = rospy.Time.now()
            message.status = status
            message.result = result
            if not rospy.is_shutdown():
                self.result_pub.publish(message)
            self.publish_status()

    def publish_feedback(self, status, feedback) -> None:
        with self.lock:
            message = self.ActionFeedback()
            message.header.stamp = rospy.Time.now()
            message.status = status
            message.feedback = feedback
            if not rospy.is_shutdown():
                self.feedback_pub.publish(message)

    def _handle(self, tracker: StatusTracker) -> ServerGoalHandle:
        if tracker.handle_tracker is None:
            tracker.handle_tracker = _HandleTracker(self, tracker)
            tracker.handle_destruction_time = rospy.Time.now()
        return ServerGoalHandle(tracker, self, tracker.handle_tracker)

    def internal_cancel_callback(self, goal_id) -> None:
        """A GoalID cancels that goal; an empty id with a stamp every goal up to it; empty and zero every goal."""
        with self.lock:
            if not self.started:
                return
            zero = rospy.Time()
            found = False
            for tracker in self.status_list[:]:
                own_id = tracker.status.goal_id
                if (goal_id.id == "" and goal_id.stamp == zero) or goal_id.id == own_id.id or \
                        (goal_id.stamp != zero and own_id.stamp <= goal_id.stamp):
                    found = found or goal_id.id == own_id.id
                    handle = self._handle(tracker)
                    if handle.set_cancel_requested():
                        self.cancel_callback(handle)
            if goal_id.id != "" and not found:  # a cancel before its goal: the goal is recalled when it comes
                tracker = StatusTracker(goal_id, GoalStatus.RECALLING)
                self.status_list.append(tracker)
                tracker.handle_destruction_time = rospy.Time.now()
            if goal_id.stamp > self.last_cancel:
                self.last_cancel = goal_id.stamp

    def internal_goal_callback(self, goal) -> None:
        """A new goal goes to the goal callback; one seen before is ignored (or recalled, if its cancel came first);
        one stamped at or before the last cancel's stamp is canceled at once."""
        with self.lock:
            if not self.started:
                return
            for tracker in self.status_list[:]:
                if goal.goal_id.id == tracker.status.goal_id.id:
                    if tracker.status.status == GoalStatus.RECALLING:
                        tracker.status.status = GoalStatus.RECALLED
                        self.publish_result(tracker.status, self.ActionResultType())
                    if tracker.handle_tracker is None:
                        tracker.handle_destruction_time = rospy.Time.now()
                    return
            tracker = StatusTracker(None, None, goal)
            self.status_list.append(tracker)
            tracker.handle_tracker = _HandleTracker(self, tracker)
            handle = ServerGoalHandle(tracker, self, tracker.handle_tracker)
            if goal.goal_id.stamp != rospy.Time() and goal.goal_id.stamp <= self.last_cancel:
                handle.set_canceled(None, "This goal handle was canceled by the action server because its timestamp "
                                          "is before the timestamp of the last cancel request")
            else:
                self.goal_callback(handle)

    def publish_status_async(self, event) -> None:
        with self.lock:
            if self.started:
                self.publish_status()

    def publish_status(self) -> None:
        """Publish every goal's status, forgetting those untracked for longer than ``status_list_timeout``."""
        with self.lock:
            now = rospy.Time.now()
            self.status_list = [tracker for tracker in self.status_list
                                if tracker.handle_destruction_time == rospy.Time()
                                or tracker.handle_destruction_time + self.status_list_timeout >= now]
            status_array = GoalStatusArray()
            status_array.status_list = [tracker.status for tracker in self.status_list]
            status_array.header.stamp = rospy.Time.now()
            if not rospy.is_shutdown():
                self.status_pub.publish(status_array)
