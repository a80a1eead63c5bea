"""rclpy.action.server: ActionServer built as rcl_action builds it, from three services and two topics.

``<action>/_action/send_goal``, ``get_result`` and ``cancel_goal`` are served through the grader's service routing and
``_action/feedback`` and ``_action/status`` (action_msgs/GoalStatusArray, transient local) are published like any
topic, so the recording holds goals, feedback, status and results where real ROS carries them. Goal states follow
rcl_action's state machine; the goal, cancel and result requests are taken as one waitable, and each accepted goal's
execute callback runs as an executor task, as rclpy schedules it.
"""
from __future__ import annotations

import functools
import traceback
from enum import Enum

from .._rclpy_pybind11 import RCLError
from ..executors import await_or_execute
from ..publisher import Publisher
from ..qos import QoSProfile, qos_profile_action_status_default, qos_profile_services_default
from ..service import Service
from ..task import Future
from ..waitable import NumberOfEntities, Waitable
from ._states import GoalEvent, transition

__all__ = ["ActionServer", "CancelResponse", "GoalEvent", "GoalResponse", "ServerGoalHandle"]


class GoalResponse(Enum):
    """Possible goal responses."""

    REJECT = 1
    ACCEPT = 2


class CancelResponse(Enum):
    """Possible cancel responses."""

    REJECT = 1
    ACCEPT = 2


def _status_constants():
    from action_msgs.msg import GoalStatus
    return GoalStatus


class ServerGoalHandle:
    """An accepted goal: its request, state, feedback and terminal states (made by the ActionServer only)."""

    def __init__(self, action_server, goal_info, goal_request) -> None:
        self._action_server = action_server
        self._goal_info = goal_info
        self._goal_request = goal_request
        self._state = _status_constants().STATUS_ACCEPTED
        self._destroyed = False

    def __eq__(self, other) -> bool:
        return self.goal_id == other.goal_id

    def __ne__(self, other) -> bool:
        return self.goal_id != other.goal_id

    @property
    def request(self):
        return self._goal_request

    @property
    def goal_id(self):
        return self._goal_info.goal_id

    @property
    def is_active(self) -> bool:
        status = _status_constants()
        return not self._destroyed and self._state in (status.STATUS_ACCEPTED, status.STATUS_EXECUTING,
                                                       status.STATUS_CANCELING)

    @property
    def is_cancel_requested(self) -> bool:
        return _status_constants().STATUS_CANCELING == self.status

    @property
    def status(self) -> int:
        return _status_constants().STATUS_UNKNOWN if self._destroyed else self._state

    def _update_state(self, event: GoalEvent) -> None:
        if self._destroyed:
            return
        self._state = transition(self._state, event)
        self._action_server._publish_status()
        if not self.is_active:
            self._action_server.notify_goal_done()

    def execute(self, execute_callback=None) -> None:
        # a goal cancelled before it executes stays CANCELING; its execute callback still runs to handle that
        if not self.is_cancel_requested:
            self._update_state(GoalEvent.EXECUTE)
        self._action_server.notify_execute(self, execute_callback)

    def publish_feedback(self, feedback) -> None:
        if not isinstance(feedback, self._action_server.action_type.Feedback):
            raise TypeError()
        if self._destroyed:
            return
        message = self._action_server.action_type.Impl.FeedbackMessage()
        message.goal_id = self.goal_id
        message.feedback = feedback
        self._action_server._feedback_publisher.publish(message)

    def succeed(self) -> None:
        self._update_state(GoalEvent.SUCCEED)

    def abort(self) -> None:
        self._update_state(GoalEvent.ABORT)

    def canceled(self) -> None:
        self._update_state(GoalEvent.CANCELED)

    def destroy(self) -> None:
        self._destroyed = True


def default_handle_accepted_callback(goal_handle) -> None:
    """Execute the goal."""
    goal_handle.execute()


def default_goal_callback(goal_request) -> GoalResponse:
    """Accept all goals."""
    return GoalResponse.ACCEPT


def default_cancel_callback(cancel_request) -> CancelResponse:
    """No cancellations."""
    return CancelResponse.REJECT


class ActionServer(Waitable):
    """ROS Action server."""

    def __init__(self, node, action_type, action_name: str, execute_callback, *, callback_group=None,
                 goal_callback=default_goal_callback, handle_accepted_callback=default_handle_accepted_callback,
                 cancel_callback=default_cancel_callback, goal_service_qos_profile=qos_profile_services_default,
                 result_service_qos_profile=qos_profile_services_default,
                 cancel_service_qos_profile=qos_profile_services_default,
                 feedback_pub_qos_profile=QoSProfile(depth=10),
                 status_pub_qos_profile=qos_profile_action_status_default, result_timeout: int = 900) -> None:
        if callback_group is None:
            callback_group = node.default_callback_group
        super().__init__(callback_group)
        self.register_handle_accepted_callback(handle_accepted_callback)
        self.register_goal_callback(goal_callback)
        self.register_cancel_callback(cancel_callback)
        self.register_execute_callback(execute_callback)
        from action_msgs.msg import GoalStatusArray
        from action_msgs.srv import CancelGoal
        self._node = node
        self._action_type = action_type
        impl = action_type.Impl
        node.handle

        def service(srv_type, suffix: str, qos) -> Service:
            return Service(node, srv_type, node.resolve_service_name(f"{action_name}/_action/{suffix}"), None,
                           callback_group, qos)

        def publisher(msg_type, suffix: str, qos) -> Publisher:
            return Publisher(node, msg_type, node.resolve_topic_name(f"{action_name}/_action/{suffix}"), qos,
                             callback_group)
        self._goal_service = service(impl.SendGoalService, "send_goal", goal_service_qos_profile)
        self._cancel_service = service(CancelGoal, "cancel_goal", cancel_service_qos_profile)
        self._result_service = service(impl.GetResultService, "get_result", result_service_qos_profile)
        self._feedback_publisher = publisher(impl.FeedbackMessage, "feedback", feedback_pub_qos_profile)
        self._status_publisher = publisher(GoalStatusArray, "status", status_pub_qos_profile)
        self._result_timeout = result_timeout
        # key: UUID in bytes; in the order the goals were accepted, which the status array keeps
        self._goal_handles: dict[bytes, ServerGoalHandle] = {}
        self._result_futures: dict[bytes, Future] = {}
        self._node.add_waitable(self)
        self._logger = self._node.get_logger().get_child("action_server")

    def _publish_status(self) -> None:
        """Every goal the server holds, accepted order, with its state (rcl_action_get_goal_status_array)."""
        from action_msgs.msg import GoalStatus, GoalStatusArray
        message = GoalStatusArray()
        message.status_list = [GoalStatus(goal_info=handle._goal_info, status=handle._state)
                               for handle in self._goal_handles.values() if not handle._destroyed]
        self._status_publisher.publish(message)

    def _process_cancel_request(self, cancel_request):
        """rcl_action_process_cancel_request: the goals to cancel and the return code, before the callbacks."""
        from action_msgs.srv import CancelGoal
        response = CancelGoal.Response()
        wanted = bytes(cancel_request.goal_info.goal_id.uuid)
        stamp = cancel_request.goal_info.stamp
        before_ns = stamp.sec * 1_000_000_000 + stamp.nanosec
        cancelable = [h for h in self._goal_handles.values() if h.is_active]
        if any(wanted) and before_ns == 0:
            match = self._goal_handles.get(wanted)
            if match is None:
                response.return_code = CancelGoal.Response.ERROR_UNKNOWN_GOAL_ID
            elif match.is_active:
                response.goals_canceling = [match._goal_info]
            else:
                response.return_code = CancelGoal.Response.ERROR_GOAL_TERMINATED
            return response
        if not any(wanted) and before_ns == 0:
            before_ns = 2 ** 63 - 1
        response.goals_canceling = [
            h._goal_info for h in cancelable
            if h._goal_info.stamp.sec * 1_000_000_000 + h._goal_info.stamp.nanosec <= before_ns
            or bytes(h.goal_id.uuid) == wanted]
        return response

    async def _execute_goal_request(self, request_header_and_message) -> None:
        from action_msgs.msg import GoalInfo
        request_header, goal_request = request_header_and_message
        goal_uuid = goal_request.goal_id
        goal_info = GoalInfo()
        goal_info.goal_id = goal_uuid
        self._logger.debug("New goal request with ID: {0}".format(goal_uuid.uuid))
        accepted = False
        if bytes(goal_uuid.uuid) not in self._goal_handles:
            response = await await_or_execute(self._goal_callback, goal_request.goal)
            if not isinstance(response, GoalResponse):
                self._logger.warning("Goal request callback did not return a GoalResponse type. Rejecting goal.")
            else:
                accepted = GoalResponse.ACCEPT == response
        if accepted:
            goal_info.stamp = self._node.get_clock().now().to_msg()
            goal_handle = ServerGoalHandle(self, goal_info, goal_request.goal)
            self._goal_handles[bytes(goal_uuid.uuid)] = goal_handle
            self._result_futures[bytes(goal_uuid.uuid)] = Future()
            self.add_future(self._result_futures[bytes(goal_uuid.uuid)])
        response_msg = self._action_type.Impl.SendGoalService.Response()
        response_msg.accepted = accepted
        response_msg.stamp = goal_info.stamp
        self._goal_service.send_response(response_msg, request_header)
        if not accepted:
            self._logger.debug("New goal rejected: {0}".format(goal_uuid.uuid))
            return
        self._logger.debug("New goal accepted: {0}".format(goal_uuid.uuid))
        await await_or_execute(self._handle_accepted_callback, goal_handle)

    async def _execute_goal(self, execute_callback, goal_handle) -> None:
        goal_uuid = goal_handle.goal_id.uuid
        self._logger.debug("Executing goal with ID {0}".format(goal_uuid))
        try:
            execute_result = await await_or_execute(execute_callback, goal_handle)
        except Exception as ex:  # noqa: BLE001 - as rclpy: the client still gets a result
            execute_result = self._action_type.Result()
            self._logger.error("Error raised in execute callback: {0}".format(ex))
            traceback.print_exc()
        if goal_handle.is_active:
            self._logger.warning("Goal state not set, assuming aborted. Goal ID: {0}".format(goal_uuid))
            goal_handle.abort()
        self._logger.debug("Goal with ID {0} finished with state {1}".format(goal_uuid, goal_handle.status))
        result_response = self._action_type.Impl.GetResultService.Response()
        result_response.status = goal_handle.status
        result_response.result = execute_result
        self._result_futures[bytes(goal_uuid)].set_result(result_response)

    async def _execute_cancel_request(self, request_header_and_message) -> None:
        request_header, cancel_request = request_header_and_message
        self._logger.debug("Cancel request received: {0}".format(cancel_request))
        cancel_response = self._process_cancel_request(cancel_request)
        for goal_info in list(cancel_response.goals_canceling):
            goal_handle = self._goal_handles[bytes(goal_info.goal_id.uuid)]
            response = await await_or_execute(self._cancel_callback, goal_handle)
            if CancelResponse.ACCEPT == response:
                try:
                    # the goal may have reached a terminal state in the cancel callback
                    goal_handle._update_state(GoalEvent.CANCEL_GOAL)
                except RCLError as ex:
                    self._logger.debug("Failed to cancel goal in cancel callback: {0}".format(ex))
                    cancel_response.goals_canceling.remove(goal_info)
            else:
                cancel_response.goals_canceling.remove(goal_info)
        self._cancel_service.send_response(cancel_response, request_header)

    async def _execute_get_result_request(self, request_header_and_message) -> None:
        request_header, result_request = request_header_and_message
        goal_uuid = result_request.goal_id.uuid
        self._logger.debug("Result request received for goal with ID: {0}".format(goal_uuid))
        if bytes(goal_uuid) not in self._goal_handles:
            self._logger.debug("Sending result response for unknown goal ID: {0}".format(goal_uuid))
            result_response = self._action_type.Impl.GetResultService.Response()
            result_response.status = _status_constants().STATUS_UNKNOWN
            self._result_service.send_response(result_response, request_header)
            return
        self._result_futures[bytes(goal_uuid)].add_done_callback(
            functools.partial(self._send_result_response, request_header))

    def _send_result_response(self, request_header, future) -> None:
        self._result_service.send_response(future.result(), request_header)

    @property
    def action_type(self):
        return self._action_type

    # -- Waitable ---------------------------------------------------------------------------------------------------
    def is_ready(self, wait_set) -> bool:
        return (self._goal_service.has_request() or self._cancel_service.has_request()
                or self._result_service.has_request())

    def take_data(self) -> dict:
        """One request of each kind that has one waiting."""
        data = {}
        for key, service in (("goal", self._goal_service), ("cancel", self._cancel_service),
                             ("result", self._result_service)):
            if service.has_request():
                request, header = service.take_request()
                data[key] = (header, request)
        return data

    async def execute(self, taken_data) -> None:
        if "goal" in taken_data:
            await self._execute_goal_request(taken_data["goal"])
        if "cancel" in taken_data:
            await self._execute_cancel_request(taken_data["cancel"])
        if "result" in taken_data:
            await self._execute_get_result_request(taken_data["result"])

    def get_num_entities(self) -> NumberOfEntities:
        return NumberOfEntities(0, 0, 1, 0, 3)

    def add_to_wait_set(self, wait_set) -> None:
        pass

    # -- callbacks --------------------------------------------------------------------------------------------------
    def notify_execute(self, goal_handle, execute_callback) -> None:
        if execute_callback is None:
            if self._execute_callback is None:
                return
            execute_callback = self._execute_callback
        self._node.executor.create_task(self._execute_goal, execute_callback, goal_handle)

    def notify_goal_done(self) -> None:
        """A goal reached a terminal state (rcl_action starts its result timeout, which no run outlasts)."""

    def register_handle_accepted_callback(self, handle_accepted_callback) -> None:
        self._handle_accepted_callback = handle_accepted_callback or default_handle_accepted_callback

    def register_goal_callback(self, goal_callback) -> None:
        self._goal_callback = goal_callback or default_goal_callback

    def register_cancel_callback(self, cancel_callback) -> None:
        self._cancel_callback = cancel_callback or default_cancel_callback

    def register_execute_callback(self, execute_callback) -> None:
        if not callable(execute_callback):
            raise TypeError("Failed to register goal execution callback: not callable")
        self._execute_callback = execute_callback

    def destroy(self) -> None:
        """Stop serving the action's services and publishing its topics."""
        for goal_handle in self._goal_handles.values():
            goal_handle.destroy()
        for result_future in self._result_futures.values():
            if result_future in self._futures:
                self.remove_future(result_future)
        for entity in (self._goal_service, self._cancel_service, self._result_service, self._feedback_publisher,
                       self._status_publisher):
            entity.destroy()
        self._node.remove_waitable(self)
