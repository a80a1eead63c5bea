"""rosgrade's tf2_ros (ROS 2): Buffer, TransformListener (/tf and /tf_static subscriptions on the student's node,
handled when it spins), TransformBroadcaster and StaticTransformBroadcaster."""
from __future__ import annotations

from ._core import (BufferCore, ConnectivityException, ExtrapolationException, InvalidArgumentException,
                    LookupException, TimeoutException, TransformException)

__all__ = ["Buffer", "BufferCore", "ConnectivityException", "ExtrapolationException", "InvalidArgumentException",
           "LookupException", "StaticTransformBroadcaster", "TimeoutException", "TransformBroadcaster",
           "TransformException", "TransformListener"]


def _ns(time) -> int:
    from rclpy.time import Time
    if time is None:
        return 0
    if isinstance(time, Time):
        return time.nanoseconds
    return time.sec * 1_000_000_000 + time.nanosec


class Buffer:
    """A transform buffer; lookup_transform with Time() takes the latest time every frame on the path shares."""

    def __init__(self, cache_time=None, node=None) -> None:
        self._core = BufferCore(cache_time.nanoseconds if cache_time is not None else 10_000_000_000)
        self._node = node

    def set_transform(self, transform, authority: str) -> bool:
        return self._core.set_transform(transform, authority)

    def set_transform_static(self, transform, authority: str) -> bool:
        return self._core.set_transform(transform, authority, static=True)

    def clear(self) -> None:
        self._core.clear()

    def all_frames_as_string(self) -> str:
        return self._core.all_frames_as_string()

    def _wait(self, check, timeout) -> None:
        """Block (sim time) until ``check()`` passes or ``timeout`` elapses; the listener fills the buffer only
        when something spins the node, as in real tf2_ros."""
        if timeout is None or timeout.nanoseconds <= 0:
            return
        from rosgrade_node import runtime
        sched = runtime.scheduler
        if sched is None:
            return
        deadline = sched.world_ns + timeout.nanoseconds

        def ready() -> bool:
            try:
                check()
                return True
            except TransformException:
                return False

        while not ready() and sched.world_ns < deadline:
            sched.block(deadline_ns=deadline, ready=ready)

    def lookup_transform(self, target_frame: str, source_frame: str, time, timeout=None):
        """A geometry_msgs/TransformStamped taking source_frame coordinates into target_frame."""
        t_ns = _ns(time)
        self._wait(lambda: self._core.lookup(target_frame, source_frame, t_ns), timeout)
        used, translation, rotation = self._core.lookup(target_frame, source_frame, t_ns)
        from geometry_msgs.msg import TransformStamped
        out = TransformStamped()
        out.header.frame_id = target_frame
        out.header.stamp.sec, out.header.stamp.nanosec = divmod(used, 1_000_000_000)
        out.child_frame_id = source_frame
        out.transform.translation.x, out.transform.translation.y, out.transform.translation.z = translation
        (out.transform.rotation.x, out.transform.rotation.y, out.transform.rotation.z,
         out.transform.rotation.w) = rotation
        return out

    def can_transform(self, target_frame: str, source_frame: str, time, timeout=None,
                      return_debug_tuple: bool = False):
        try:
            self.lookup_transform(target_frame, source_frame, time, timeout)
        except TransformException as exc:
            return (False, str(exc)) if return_debug_tuple else False
        return (True, "") if return_debug_tuple else True

    def lookup_transform_async(self, target_frame: str, source_frame: str, time):
        from rclpy.task import Future
        future = Future()
        try:
            future.set_result(self.lookup_transform(target_frame, source_frame, time))
        except TransformException as exc:
            future.set_exception(exc)
        return future


class TransformListener:
    """Fills a Buffer from /tf and /tf_static through subscriptions on ``node``."""

    def __init__(self, buffer: Buffer, node, *, spin_thread: bool = False, qos=None, static_qos=None) -> None:
        from rclpy.callback_groups import ReentrantCallbackGroup
        from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
        from tf2_msgs.msg import TFMessage
        qos = qos or QoSProfile(depth=100)
        static_qos = static_qos or QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                                              history=HistoryPolicy.KEEP_LAST)
        self.buffer = buffer
        self.node = node
        group = ReentrantCallbackGroup()
        self.tf_sub = node.create_subscription(TFMessage, "/tf", self.callback, qos, callback_group=group)
        self.tf_static_sub = node.create_subscription(TFMessage, "/tf_static", self.static_callback, static_qos,
                                                      callback_group=group)

    def callback(self, data) -> None:
        for transform in data.transforms:
            self.buffer.set_transform(transform, "default_authority")

    def static_callback(self, data) -> None:
        for transform in data.transforms:
            self.buffer.set_transform_static(transform, "default_authority")

    def unregister(self) -> None:
        self.node.destroy_subscription(self.tf_sub)
        self.node.destroy_subscription(self.tf_static_sub)


class TransformBroadcaster:
    """Publishes TransformStamped messages on /tf."""

    def __init__(self, node, qos=100) -> None:
        from tf2_msgs.msg import TFMessage
        self.pub_tf = node.create_publisher(TFMessage, "/tf", qos)

    def sendTransform(self, transform) -> None:  # noqa: N802 - tf2_ros' name
        from tf2_msgs.msg import TFMessage
        transforms = transform if isinstance(transform, list) else [transform]
        self.pub_tf.publish(TFMessage(transforms=transforms))


class StaticTransformBroadcaster:
    """Publishes on /tf_static (transient local: late subscribers get the last message)."""

    def __init__(self, node, qos=None) -> None:
        from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
        from tf2_msgs.msg import TFMessage
        qos = qos or QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, history=HistoryPolicy.KEEP_LAST)
        self.pub_tf = node.create_publisher(TFMessage, "/tf_static", qos)

    def sendTransform(self, transform) -> None:  # noqa: N802 - tf2_ros' name
        from tf2_msgs.msg import TFMessage
        transforms = transform if isinstance(transform, list) else [transform]
        self.pub_tf.publish(TFMessage(transforms=transforms))
