"""An action server's callbacks as rclpy runs them: a coroutine execute callback, a goal callback that
returns no GoalResponse (rejected, with rclpy's warning), an execute callback that raises (ABORTED, with its error and
traceback) or returns without a terminal state (ABORTED, with a warning), a handle-accepted callback that executes
later; the client's blocking send_goal from the main thread while another thread spins.

Fibonacci is example_interfaces' under rosgrade and test_msgs' under real rclpy (the same definition).
"""
import threading
import time

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient, ActionServer, GoalResponse
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from unique_identifier_msgs.msg import UUID

try:
    from example_interfaces.action import Fibonacci
except ImportError:
    from test_msgs.action import Fibonacci

STATUS = {getattr(GoalStatus, n): n[7:] for n in dir(GoalStatus) if n.startswith("STATUS_")}
deferred = []


async def execute(goal_handle):
    order = goal_handle.request.order
    if order == 2:
        raise ValueError("order 2 is not allowed")
    if order == 3:
        return Fibonacci.Result(sequence=[0, 1, 1, 2])
    goal_handle.succeed()
    return Fibonacci.Result(sequence=[0, 1][:order + 1])


def goal_callback(goal):
    return "yes" if goal.order == 7 else GoalResponse.ACCEPT


def handle_accepted(goal_handle):
    if goal_handle.request.order == 0:
        deferred.append(goal_handle)  # executed later, from the main thread
    else:
        goal_handle.execute()


rclpy.init()
server_node = Node("callbacks_server")
client_node = Node("callbacks_client")
ActionServer(server_node, Fibonacci, "/fibonacci", execute, goal_callback=goal_callback,
             handle_accepted_callback=handle_accepted)
client = ActionClient(client_node, Fibonacci, "/fibonacci")
executor = MultiThreadedExecutor()
executor.add_node(server_node)
executor.add_node(client_node)
threading.Thread(target=executor.spin, daemon=True).start()
print("wait_for_server ->", client.wait_for_server(timeout_sec=10.0))
for order in (1, 2, 3):
    response = client.send_goal(Fibonacci.Goal(order=order), goal_uuid=UUID(uuid=[order] * 16))
    print("order", order, STATUS[response.status], list(response.result.sequence))
future = client.send_goal_async(Fibonacci.Goal(order=7))
while not future.done():
    time.sleep(0.01)
print("order 7 accepted", future.result().accepted)
future = client.send_goal_async(Fibonacci.Goal(order=0))
while not future.done() or not deferred:
    time.sleep(0.01)
handle = future.result()
result = handle.get_result_async()
time.sleep(0.3)
print("deferred goal status", STATUS[deferred[0].status], "result done", result.done())
deferred[0].execute()
while not result.done():
    time.sleep(0.01)
print("order 0", STATUS[result.result().status], list(result.result().result.sequence))
executor.shutdown()
rclpy.shutdown()
print("end")
