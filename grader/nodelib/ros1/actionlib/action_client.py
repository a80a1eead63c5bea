"""actionlib's ActionClient: goals out on ``<ns>/goal`` and ``<ns>/cancel``, each goal's comm state driven by the
server's ``status``, ``result`` and ``feedback`` topics, as python3-actionlib 1.14 drives it."""
from __future__ import annotations

import threading
import time
import weakref

import rospy
from actionlib_msgs.msg import GoalID, GoalStatus, GoalStatusArray
from std_msgs.msg import Header

from ._spec import ActionTypes, name_of_constant
from .exceptions import ActionException  # noqa: F401 - actionlib.action_client exports it


class CommState:
    """Where a goal is from the client's side."""

    WAITING_FOR_GOAL_ACK = 0
    PENDING = 1
    ACTIVE = 2
    WAITING_FOR_RESULT = 3
    WAITING_FOR_CANCEL_ACK = 4
    RECALLING = 5
    PREEMPTING = 6
    DONE = 7
    LOST = 8


class TerminalState:
    """The goal statuses a goal ends in."""

    RECALLED = GoalStatus.RECALLED
    REJECTED = GoalStatus.REJECTED
    PREEMPTED = GoalStatus.PREEMPTED
    ABORTED = GoalStatus.ABORTED
    SUCCEEDED = GoalStatus.SUCCEEDED
    LOST = GoalStatus.LOST


get_name_of_constant = name_of_constant
GoalStatus.to_string = classmethod(name_of_constant)
CommState.to_string = classmethod(name_of_constant)
TerminalState.to_string = classmethod(name_of_constant)

_S, _C = GoalStatus, CommState
_INVALID = None  # a status the server may not report in that comm state: logged, nothing changes
# For each comm state: the comm states a reported goal status walks the goal through ((): it stays). A status
# missing from a row is invalid there.
_PATHS: dict[int, dict[int, tuple[int, ...]]] = {
    _C.WAITING_FOR_GOAL_ACK: {
        _S.PENDING: (_C.PENDING,), _S.ACTIVE: (_C.ACTIVE,), _S.REJECTED: (_C.PENDING, _C.WAITING_FOR_RESULT),
        _S.RECALLING: (_C.PENDING, _C.RECALLING), _S.RECALLED: (_C.PENDING, _C.WAITING_FOR_RESULT),
        _S.PREEMPTED: (_C.ACTIVE, _C.PREEMPTING, _C.WAITING_FOR_RESULT),
        _S.SUCCEEDED: (_C.ACTIVE, _C.WAITING_FOR_RESULT), _S.ABORTED: (_C.ACTIVE, _C.WAITING_FOR_RESULT),
        _S.PREEMPTING: (_C.ACTIVE, _C.PREEMPTING)},
    _C.PENDING: {
        _S.PENDING: (), _S.ACTIVE: (_C.ACTIVE,), _S.REJECTED: (_C.WAITING_FOR_RESULT,),
        _S.RECALLING: (_C.RECALLING,), _S.RECALLED: (_C.RECALLING, _C.WAITING_FOR_RESULT),
        _S.PREEMPTED: (_C.ACTIVE, _C.PREEMPTING, _C.WAITING_FOR_RESULT),
        _S.SUCCEEDED: (_C.ACTIVE, _C.WAITING_FOR_RESULT), _S.ABORTED: (_C.ACTIVE, _C.WAITING_FOR_RESULT),
        _S.PREEMPTING: (_C.ACTIVE, _C.PREEMPTING)},
    _C.ACTIVE: {
        _S.ACTIVE: (), _S.PREEMPTED: (_C.PREEMPTING, _C.WAITING_FOR_RESULT),
        _S.SUCCEEDED: (_C.WAITING_FOR_RESULT,), _S.ABORTED: (_C.WAITING_FOR_RESULT,),
        _S.PREEMPTING: (_C.PREEMPTING,)},
    _C.WAITING_FOR_RESULT: {
        _S.ACTIVE: (), _S.REJECTED: (), _S.RECALLED: (), _S.PREEMPTED: (), _S.SUCCEEDED: (), _S.ABORTED: ()},
    _C.WAITING_FOR_CANCEL_ACK: {
        _S.PENDING: (), _S.ACTIVE: (), _S.REJECTED: (_C.WAITING_FOR_RESULT,), _S.RECALLING: (_C.RECALLING,),
        _S.RECALLED: (_C.RECALLING, _C.WAITING_FOR_RESULT),
        _S.PREEMPTED: (_C.PREEMPTING, _C.WAITING_FOR_RESULT), _S.SUCCEEDED: (_C.PREEMPTING, _C.WAITING_FOR_RESULT),
        _S.ABORTED: (_C.PREEMPTING, _C.WAITING_FOR_RESULT), _S.PREEMPTING: (_C.PREEMPTING,)},
    _C.RECALLING: {
        _S.REJECTED: (_C.WAITING_FOR_RESULT,), _S.RECALLING: (), _S.RECALLED: (_C.WAITING_FOR_RESULT,),
        _S.PREEMPTED: (_C.PREEMPTING, _C.WAITING_FOR_RESULT), _S.SUCCEEDED: (_C.PREEMPTING, _C.WAITING_FOR_RESULT),
        _S.ABORTED: (_C.PREEMPTING, _C.WAITING_FOR_RESULT), _S.PREEMPTING: (_C.PREEMPTING,)},
    _C.PREEMPTING: {
        _S.PREEMPTED: (_C.WAITING_FOR_RESULT,), _S.SUCCEEDED: (_C.WAITING_FOR_RESULT,),
        _S.ABORTED: (_C.WAITING_FOR_RESULT,), _S.PREEMPTING: ()},
    _C.DONE: {_S.REJECTED: (), _S.RECALLED: (), _S.PREEMPTED: (), _S.SUCCEEDED: (), _S.ABORTED: ()},
}
_KNOWN = frozenset(range(_S.PENDING, _S.RECALLED + 1))  # LOST (9) is no status a server reports
_TERMINAL = (_S.PREEMPTED, _S.SUCCEEDED, _S.ABORTED, _S.REJECTED, _S.RECALLED, _S.LOST)
_goal_count = [1]  # one sequence of goal ids per process, as actionlib's module global


class CommStateMachine:
    """One goal's state on the client: the last status and result the server reported for it."""

    def __init__(self, action_goal, transition_cb, feedback_cb, send_goal_fn, send_cancel_fn) -> None:
        self.action_goal = action_goal
        self.transition_cb = transition_cb
        self.feedback_cb = feedback_cb
        self.send_goal_fn = send_goal_fn
        self.send_cancel_fn = send_cancel_fn
        self.state = CommState.WAITING_FOR_GOAL_ACK
        self.mutex = threading.RLock()
        self.latest_goal_status = GoalStatus(status=GoalStatus.PENDING)
        self.latest_result = None

    def __eq__(self, other) -> bool:
        return self.action_goal.goal_id.id == other.action_goal.goal_id.id

    def __hash__(self) -> int:
        return hash(self.action_goal.goal_id.id)

    def set_state(self, state: int) -> None:
        self.state = state

    def transition_to(self, state: int) -> None:
        self.state = state
        if self.transition_cb:
            self.transition_cb(ClientGoalHandle(self))

    def update_status(self, status_array) -> None:
        """Follow the server's status of this goal; a goal the server no longer lists while it should is LOST."""
        with self.mutex:
            if self.state == CommState.DONE:
                return
            status = next((s for s in status_array.status_list if s.goal_id.id == self.action_goal.goal_id.id), None)
            if status is None:
                if self.state not in (CommState.WAITING_FOR_GOAL_ACK, CommState.WAITING_FOR_RESULT, CommState.DONE):
                    self.latest_goal_status.status = GoalStatus.LOST
                    self.transition_to(CommState.DONE)
                return
            self.latest_goal_status = status
            if status.status not in _KNOWN:
                rospy.logerr("Got an unknown status from the ActionServer: %i" % status.status)
                return
            path = _PATHS[self.state].get(status.status, _INVALID)
            if path is _INVALID:
                rospy.logerr("Invalid goal status transition from %s to %s" %
                             (CommState.to_string(self.state), GoalStatus.to_string(status.status)))
                return
            for state in path:
                self.transition_to(state)

    def update_result(self, action_result) -> None:
        if self.action_goal.goal_id.id != action_result.status.goal_id.id:
            return
        with self.mutex:
            self.latest_goal_status = action_result.status
            self.latest_result = action_result
            if self.state == CommState.DONE:
                rospy.logerr("Got a result when we were already in the DONE state")
                return
            self.update_status(GoalStatusArray(status_list=[action_result.status]))
            self.transition_to(CommState.DONE)

    def update_feedback(self, action_feedback) -> None:
        if self.action_goal.goal_id.id != action_feedback.status.goal_id.id:
            return
        if self.feedback_cb and self.state != CommState.DONE:
            self.feedback_cb(ClientGoalHandle(self), action_feedback.feedback)


class ClientGoalHandle:
    """A client's view of one goal it sent."""

    def __init__(self, comm_state_machine: CommStateMachine) -> None:
        self.comm_state_machine = comm_state_machine

    def __eq__(self, other) -> bool:
        return bool(other) and self.comm_state_machine == other.comm_state_machine

    def __ne__(self, other) -> bool:
        return not self.__eq__(other)

    def __hash__(self) -> int:
        return hash(self.comm_state_machine)

    def cancel(self) -> None:
        """Ask the server to cancel this goal."""
        with self.comm_state_machine.mutex:
            self.comm_state_machine.send_cancel_fn(
                GoalID(stamp=rospy.Time(0), id=self.comm_state_machine.action_goal.goal_id.id))
            self.comm_state_machine.transition_to(CommState.WAITING_FOR_CANCEL_ACK)

    def get_comm_state(self) -> int:
        return self.comm_state_machine.state

    def get_goal_status(self) -> int:
        return self.comm_state_machine.latest_goal_status.status

    def get_goal_status_text(self) -> str:
        return self.comm_state_machine.latest_goal_status.text

    def get_result(self):
        """The result message, or None before one came."""
        latest = self.comm_state_machine.latest_result
        return latest.result if latest else None

    def get_terminal_state(self) -> int:
        with self.comm_state_machine.mutex:
            if self.comm_state_machine.state != CommState.DONE:
                rospy.logwarn("Asking for the terminal state when we're in [%s]",
                              CommState.to_string(self.comm_state_machine.state))
            status = self.comm_state_machine.latest_goal_status.status
            if status in _TERMINAL:
                return status
            rospy.logerr("Asking for a terminal state, but the goal status is %d", status)
            return GoalStatus.LOST


class GoalManager:
    """The client's goals, held weakly: a goal whose handles are all dropped gets no more callbacks."""

    def __init__(self, action_spec: type) -> None:
        self.list_mutex = threading.RLock()
        self.statuses: list[weakref.ref] = []
        self.send_goal_fn = None
        self.cancel_fn = None
        types = ActionTypes(action_spec)
        self.ActionSpec, self.ActionGoal = types.ActionSpec, types.ActionGoal
        self.ActionResult, self.ActionFeedback = types.ActionResult, types.ActionFeedback

    def register_send_goal_fn(self, fn) -> None:
        self.send_goal_fn = fn

    def register_cancel_fn(self, fn) -> None:
        self.cancel_fn = fn

    def _generate_id(self):
        number = _goal_count[0]
        _goal_count[0] += 1
        now = rospy.Time.now()
        return GoalID(id="%s-%i-%.3f" % (rospy.get_caller_id(), number, now.to_sec()), stamp=now)

    def init_goal(self, goal, transition_cb=None, feedback_cb=None) -> ClientGoalHandle:
        action_goal = self.ActionGoal(header=Header(), goal_id=self._generate_id(), goal=goal)
        action_goal.header.stamp = rospy.get_rostime()
        machine = CommStateMachine(action_goal, transition_cb, feedback_cb, self.send_goal_fn, self.cancel_fn)
        with self.list_mutex:
            self.statuses.append(weakref.ref(machine))
        self.send_goal_fn(action_goal)
        return ClientGoalHandle(machine)

    def _live(self) -> list[CommStateMachine]:
        with self.list_mutex:
            self.statuses = [ref for ref in self.statuses if ref() is not None]
            return [machine for machine in (ref() for ref in self.statuses) if machine is not None]

    def update_statuses(self, status_array) -> None:
        for machine in self._live():
            machine.update_status(status_array)

    def update_results(self, action_result) -> None:
        for machine in self._live():
            machine.update_result(action_result)

    def update_feedbacks(self, action_feedback) -> None:
        for machine in self._live():
            machine.update_feedback(action_feedback)


class ActionClient:
    """Sends goals of one action under ``ns`` and tracks them."""

    def __init__(self, ns: str, ActionSpec: type) -> None:
        self.ns = ns
        self.last_status_msg = None
        types = ActionTypes(ActionSpec)
        self.ActionSpec, self.ActionGoal = types.ActionSpec, types.ActionGoal
        self.ActionResult, self.ActionFeedback = types.ActionResult, types.ActionFeedback
        base = rospy.remap_name(ns)
        pub_queue = rospy.get_param("actionlib_client_pub_queue_size", 10)
        self.pub_queue_size = pub_queue if pub_queue >= 0 else 10
        self.pub_goal = rospy.Publisher(base + "/goal", self.ActionGoal, queue_size=self.pub_queue_size)
        self.pub_cancel = rospy.Publisher(base + "/cancel", GoalID, queue_size=self.pub_queue_size)
        self.manager = GoalManager(ActionSpec)
        self.manager.register_send_goal_fn(self.pub_goal.publish)
        self.manager.register_cancel_fn(self.pub_cancel.publish)
        sub_queue = rospy.get_param("actionlib_client_sub_queue_size", -1)
        self.sub_queue_size = sub_queue if sub_queue >= 0 else None
        self.status_sub = rospy.Subscriber(base + "/status", GoalStatusArray, callback=self._status_cb,
                                           queue_size=self.sub_queue_size)
        self.result_sub = rospy.Subscriber(base + "/result", self.ActionResult, callback=self._result_cb,
                                           queue_size=self.sub_queue_size)
        self.feedback_sub = rospy.Subscriber(base + "/feedback", self.ActionFeedback, callback=self._feedback_cb,
                                             queue_size=self.sub_queue_size)

    def stop(self) -> None:
        for endpoint in (self.pub_goal, self.pub_cancel, self.status_sub, self.result_sub, self.feedback_sub):
            endpoint.unregister()

    def send_goal(self, goal, transition_cb=None, feedback_cb=None) -> ClientGoalHandle:
        return self.manager.init_goal(goal, transition_cb, feedback_cb)

    def cancel_all_goals(self) -> None:
        self.pub_cancel.publish(GoalID(stamp=rospy.Time.from_sec(0.0), id=""))

    def cancel_goals_at_and_before_time(self, time) -> None:
        self.pub_cancel.publish(GoalID(stamp=time, id=""))

    def wait_for_action_server_to_start(self, timeout=rospy.Duration(0.0)) -> bool:
        return self.wait_for_server(timeout)

    def _server_connected(self) -> bool:
        """A server has published its status and is connected both ways: it takes our goals and cancels, and
        we take its results and feedback (so a goal sent now loses nothing)."""
        return self.last_status_msg is not None and all(
            endpoint.get_num_connections() > 0
            for endpoint in (self.pub_goal, self.pub_cancel, self.result_sub, self.feedback_sub))

    def wait_for_server(self, timeout=rospy.Duration(0.0)) -> bool:
        """Poll every 10 ms (wall) until a server is connected; a zero timeout waits for ever."""
        deadline = rospy.get_rostime() + timeout
        while not rospy.is_shutdown():
            if self._server_connected():
                return True
            if timeout != rospy.Duration(0.0) and rospy.get_rostime() >= deadline:
                break
            time.sleep(0.01)
        return False

    def _status_cb(self, msg) -> None:
        self.last_status_msg = msg
        self.manager.update_statuses(msg)

    def _result_cb(self, msg) -> None:
        self.manager.update_results(msg)

    def _feedback_cb(self, msg) -> None:
        self.manager.update_feedbacks(msg)
