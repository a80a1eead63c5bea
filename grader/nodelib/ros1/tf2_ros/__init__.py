"""rosgrade's tf2_ros: Buffer, TransformListener and the (static) broadcasters of ROS 1 Noetic's tf2_ros.

The buffer keeps transforms with tf's lookup rules (it shares tf's Transformer); a lookup with a timeout polls at
20 Hz in ROS time, as tf2_ros does. The exceptions are tf's, which in real ROS are tf2's too.
"""
from __future__ import annotations

from tf import ConnectivityException, ExtrapolationException, LookupException, Transformer
from tf import Exception as TransformException

__all__ = ["Buffer", "BufferInterface", "ConnectivityException", "ExtrapolationException", "InvalidArgumentException",
           "LookupException", "StaticTransformBroadcaster", "TimeoutException", "TransformBroadcaster",
           "TransformException", "TransformListener", "TransformRegistration", "TypeException"]


class InvalidArgumentException(TransformException):
    """A frame name or time that tf2 cannot use."""


class TimeoutException(TransformException):
    """A transform did not become available in time."""


class TypeException(TransformException):
    """Buffer.transform was given a type no conversion is registered for (import tf2_geometry_msgs)."""


for _cls in (InvalidArgumentException, TimeoutException, TypeException):
    _cls.__module__ = "tf2"


class TransformRegistration:
    """Which function transforms which stamped message type (tf2_geometry_msgs registers its own on import)."""

    __type_map: dict = {}

    def add(self, key, callback) -> None:
        TransformRegistration.__type_map[key] = callback

    def get(self, key):
        if key not in TransformRegistration.__type_map:
            raise TypeException("Type %s if not loaded or supported" % str(key))
        return TransformRegistration.__type_map[key]


class BufferInterface:
    """Buffer.transform, on top of lookup_transform."""

    def __init__(self) -> None:
        self.registration = TransformRegistration()

    def transform(self, object_stamped, target_frame, timeout=None, new_type=None):
        """``object_stamped`` (PointStamped, PoseStamped, ...) expressed in ``target_frame``."""
        import rospy
        do_transform = self.registration.get(type(object_stamped))
        res = do_transform(object_stamped, self.lookup_transform(
            target_frame, object_stamped.header.frame_id, object_stamped.header.stamp,
            timeout if timeout is not None else rospy.Duration(0.0)))
        if new_type is None:
            return res
        raise TypeException("Type %s if not loaded or supported" % str(new_type))


class Buffer(BufferInterface):
    """Holds transforms for ``cache_time`` (default 10 s) and answers lookups between any two connected frames."""

    def __init__(self, cache_time=None, debug=True) -> None:
        super().__init__()
        self._core = Transformer(True, cache_time)

    # -- filling it ------------------------------------------------------------------------------------------------
    def set_transform(self, transform, authority) -> None:
        self._core._store(transform, static=False)

    def set_transform_static(self, transform, authority) -> None:
        self._core._store(transform, static=True)

    def clear(self) -> None:
        self._core.clear()

    # -- asking it -------------------------------------------------------------------------------------------------
    def lookup_transform(self, target_frame, source_frame, time, timeout=None):
        """geometry_msgs/TransformStamped taking ``source_frame`` coordinates into ``target_frame`` at ``time``
        (time 0: the latest available), waiting up to ``timeout`` of ROS time for it."""
        self.can_transform(target_frame, source_frame, time, timeout)
        return self._stamped(target_frame, source_frame, *self._core._lookup_at(target_frame, source_frame, time))

    def lookup_transform_full(self, target_frame, target_time, source_frame, source_time, fixed_frame, timeout=None):
        """The transform from ``source_frame`` at ``source_time`` to ``target_frame`` at ``target_time``, through
        ``fixed_frame``, which is assumed not to move between the two times."""
        self.can_transform_full(target_frame, target_time, source_frame, source_time, fixed_frame, timeout)
        source_time_ns, into_fixed_t, into_fixed_r = self._core._lookup_at(fixed_frame, source_frame, source_time)
        _, out_t, out_r = self._core._lookup_at(target_frame, fixed_frame, target_time)
        from tf import _qmul, _rotate
        moved = _rotate(out_r, into_fixed_t)
        translation = (moved[0] + out_t[0], moved[1] + out_t[1], moved[2] + out_t[2])
        return self._stamped(target_frame, source_frame, source_time_ns, translation, _qmul(out_r, into_fixed_r))

    def can_transform(self, target_frame, source_frame, time, timeout=None, return_debug_tuple=False):
        """1 if the transform is available (after polling at 20 Hz for up to ``timeout`` of ROS time), else 0:
        tf2's core answers with ints, which tf2_ros passes on."""
        ok, error = self._poll(lambda: self._core._lookup_at(target_frame, source_frame, time), timeout)
        return (ok, error) if return_debug_tuple else ok

    def can_transform_full(self, target_frame, target_time, source_frame, source_time, fixed_frame, timeout=None,
                           return_debug_tuple=False):
        def both():
            self._core._lookup_at(fixed_frame, source_frame, source_time)
            self._core._lookup_at(target_frame, fixed_frame, target_time)
        ok, error = self._poll(both, timeout)
        return (ok, error) if return_debug_tuple else ok

    def all_frames_as_string(self) -> str:
        return self._core.allFramesAsString()

    def all_frames_as_yaml(self) -> str:
        return "".join("%s: \n  parent: '%s'\n" % (child, parent) for child, parent in self._core._parents.items())

    # -- helpers ---------------------------------------------------------------------------------------------------
    @staticmethod
    def _poll(attempt, timeout) -> tuple[int, str]:
        """Run ``attempt`` until it succeeds or ``timeout`` (ROS time) passes, sleeping on a 20 Hz rospy.Rate."""
        import rospy

        def once():
            try:
                attempt()
            except TransformException as error:
                return 0, str(error)
            return 1, ""

        ok, error = once()
        if timeout is None or ok:
            return ok, error
        start = rospy.Time.now()
        rate = rospy.Rate(20.0)
        while not ok and rospy.Time.now() < start + timeout and not rospy.is_shutdown():
            rate.sleep()
            ok, error = once()
        return ok, error

    @staticmethod
    def _stamped(target_frame, source_frame, t_ns, translation, rotation):
        import rospy
        from geometry_msgs.msg import TransformStamped
        out = TransformStamped()
        out.header.frame_id = target_frame
        out.header.stamp = rospy.Time(t_ns // 1_000_000_000, t_ns % 1_000_000_000)
        out.child_frame_id = source_frame
        out.transform.translation.x, out.transform.translation.y, out.transform.translation.z = (
            float(v) for v in translation)
        r = out.transform.rotation
        r.x, r.y, r.z, r.w = (float(v) for v in rotation)
        return out


class TransformListener:
    """Feeds a Buffer from /tf and /tf_static."""

    def __init__(self, buffer, queue_size=None, buff_size=65536, tcp_nodelay=False) -> None:
        import rospy
        from tf2_msgs.msg import TFMessage
        self.buffer = buffer
        self.tf_sub = rospy.Subscriber("/tf", TFMessage, self.callback, queue_size=queue_size)
        self.tf_static_sub = rospy.Subscriber("/tf_static", TFMessage, self.static_callback, queue_size=queue_size)

    def __del__(self) -> None:
        self.unregister()

    def unregister(self) -> None:
        for name in ("tf_sub", "tf_static_sub"):
            sub = getattr(self, name, None)
            if sub is not None:
                sub.unregister()
                setattr(self, name, None)

    def callback(self, data) -> None:
        for transform in data.transforms:
            self.buffer.set_transform(transform, "default_authority")

    def static_callback(self, data) -> None:
        for transform in data.transforms:
            self.buffer.set_transform_static(transform, "default_authority")


class TransformBroadcaster:
    """Publishes geometry_msgs/TransformStamped (one or a list) as tf2_msgs/TFMessage on /tf."""

    def __init__(self, queue_size=100) -> None:
        import rospy
        from tf2_msgs.msg import TFMessage
        self._message = TFMessage
        self.pub_tf = rospy.Publisher("/tf", TFMessage, queue_size=queue_size)

    def sendTransform(self, transform) -> None:
        transforms = transform if isinstance(transform, list) else [transform]
        self.pub_tf.publish(self._message(transforms))


class StaticTransformBroadcaster(TransformBroadcaster):
    """Publishes transforms that never change on the latched /tf_static."""

    def __init__(self, queue_size=100) -> None:
        import rospy
        from tf2_msgs.msg import TFMessage
        self._message = TFMessage
        self.pub_tf = rospy.Publisher("/tf_static", TFMessage, queue_size=queue_size, latch=True)
