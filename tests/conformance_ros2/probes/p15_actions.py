#!/usr/bin/env python3
"""Probe 15: an action between two nodes of one process, the server under a MultiThreadedExecutor in a thread and the
client spun by the main thread, as the tutorials' clients are: a goal's acceptance, feedback and result, a cancel
while it executes (CANCELED), cancels of a finished and of an unknown goal, a rejected goal, the status each goal
handle ends with, and the error of a second terminal transition. (A client spun by another thread than the one that
sends its goals races real rclpy 7.1's send_goal_async, which registers the reply's future after sending: under
load the reply came first and the goal hung, in 5 runs of 5.)

Fibonacci is example_interfaces' under rosgrade and test_msgs' under real rclpy (the same definition).
"""
import threading
import time

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.action.client import ClientGoalHandle
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from unique_identifier_msgs.msg import UUID

try:
    from example_interfaces.action import Fibonacci
except ImportError:
    from test_msgs.action import Fibonacci

STATUS = {getattr(GoalStatus, n): n[7:] for n in dir(GoalStatus) if n.startswith("STATUS_")}
seen = {}  # what the execute callback saw, printed by the main thread (threads print in any order)


def execute(goal_handle):
    order = goal_handle.request.order
    feedback = Fibonacci.Feedback(sequence=[0, 1])
    if order == 1:
        goal_handle.succeed()
        try:
            goal_handle.succeed()
        except Exception as exc:  # noqa: BLE001 - the probe prints what real rclpy raises
            seen["second succeed"] = f"{type(exc).__name__} {exc}"
        return Fibonacci.Result(sequence=[0, 1])
    for i in range(1, order):
        if goal_handle.is_cancel_requested:
            seen["status when cancel requested"] = STATUS[goal_handle.status]
            goal_handle.canceled()
            return Fibonacci.Result(sequence=list(feedback.sequence))
        feedback.sequence.append(feedback.sequence[i] + feedback.sequence[i - 1])
        goal_handle.publish_feedback(feedback)
        time.sleep(0.2)
    goal_handle.succeed()
    return Fibonacci.Result(sequence=list(feedback.sequence))


rclpy.init()
server_node = Node("p15_server")
client_node = Node("p15_actions")
group = ReentrantCallbackGroup()
server = ActionServer(server_node, Fibonacci, "/p15_fibonacci", execute, callback_group=group,
                      goal_callback=lambda goal: GoalResponse.ACCEPT if goal.order >= 0 else GoalResponse.REJECT,
                      cancel_callback=lambda handle: CancelResponse.ACCEPT)
client = ActionClient(client_node, Fibonacci, "/p15_fibonacci", callback_group=group)
executor = MultiThreadedExecutor()
executor.add_node(server_node)
threading.Thread(target=executor.spin, daemon=True).start()
print("wait_for_server ->", client.wait_for_server(timeout_sec=10.0))
print("#REF %.6f" % (client_node.get_clock().now().nanoseconds / 1e9))
feedback = []


def wait(future):
    rclpy.spin_until_future_complete(client_node, future, timeout_sec=10.0)
    return future.result()


def spin_for(seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        rclpy.spin_once(client_node, timeout_sec=0.05)


handle = wait(client.send_goal_async(Fibonacci.Goal(order=4), feedback_callback=lambda m: feedback.append(
    list(m.feedback.sequence))))
print("goal accepted", handle.accepted)
result = wait(handle.get_result_async())
spin_for(0.5)  # feedback and status are topics: let the last ones arrive
print("result", STATUS[result.status], list(result.result.sequence))
print("feedback", feedback)
print("handle status", STATUS[handle.status])

handle = wait(client.send_goal_async(Fibonacci.Goal(order=40), feedback_callback=lambda m: feedback.append(1)))
while len(feedback) < 4:
    rclpy.spin_once(client_node, timeout_sec=0.05)
cancel = wait(handle.cancel_goal_async())
print("cancel return_code", cancel.return_code, "canceling", len(cancel.goals_canceling),
      "same goal", bytes(cancel.goals_canceling[0].goal_id.uuid) == bytes(handle.goal_id.uuid))
result = wait(handle.get_result_async())
spin_for(0.5)
print("result", STATUS[result.status], "handle status", STATUS[handle.status])
print("status when cancel requested", seen["status when cancel requested"])
again = wait(handle.cancel_goal_async())
print("cancel again return_code", again.return_code, "canceling", len(again.goals_canceling))
unknown = ClientGoalHandle(client, UUID(uuid=list(range(16))), Fibonacci.Impl.SendGoalService.Response())
gone = wait(unknown.cancel_goal_async())
print("cancel unknown return_code", gone.return_code, "canceling", len(gone.goals_canceling))

rejected = wait(client.send_goal_async(Fibonacci.Goal(order=-1)))
print("negative order accepted", rejected.accepted, "status", STATUS[rejected.status])
handle = wait(client.send_goal_async(Fibonacci.Goal(order=1)))
result = wait(handle.get_result_async())
print("order 1", STATUS[result.status], list(result.result.sequence))
print("second succeed !!", seen["second succeed"])
executor.shutdown()
rclpy.shutdown()
print("end")
