"""rclpy.wait_for_message.wait_for_message: one message from a topic, spinning a private executor meanwhile."""
from __future__ import annotations


def wait_for_message(msg_type, node, topic: str, *, qos_profile=1, time_to_wait=-1):
    """(True, message) once one arrives on ``topic``, or (False, None) after ``time_to_wait`` seconds."""
    from .executors import SingleThreadedExecutor
    from .task import Future
    got = Future()
    sub = node.create_subscription(msg_type, topic, lambda msg: got.done() or got.set_result(msg), qos_profile)
    executor = SingleThreadedExecutor(context=node.context)
    try:
        executor.add_node(node)
        executor.spin_until_future_complete(got, None if time_to_wait is None or time_to_wait < 0 else time_to_wait)
    finally:
        executor.remove_node(node)
        node.destroy_subscription(sub)
    return (True, got.result()) if got.done() else (False, None)
