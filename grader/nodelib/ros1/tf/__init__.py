"""rosgrade's tf: tf.transformations plus a TransformListener/TransformBroadcaster on /tf, as ROS 1 tf 1.13 has them.

The listener and broadcaster use only rospy's public API; rospy is imported when one is created, so
``import tf`` and ``tf.transformations`` work before (and without) ``rospy.init_node``.
"""
from __future__ import annotations

import math
import threading

from . import transformations

__all__ = ["ConnectivityException", "Exception", "ExtrapolationException", "LookupException", "Transformer",
           "TransformerROS", "TransformBroadcaster", "TransformListener", "transformations"]

_builtin_exception = Exception
_NS = 1_000_000_000


class Exception(_builtin_exception):  # noqa: A001 - tf names its base error tf.Exception (tf2.TransformException)
    """Any transform lookup failure."""


class LookupException(Exception):
    """A frame does not exist."""


class ConnectivityException(Exception):
    """The frames are in different trees."""


class ExtrapolationException(Exception):
    """The requested time is outside the buffered data."""


for _cls, _name in ((Exception, "TransformException"), (LookupException, "LookupException"),
                    (ConnectivityException, "ConnectivityException"),
                    (ExtrapolationException, "ExtrapolationException")):
    _cls.__module__, _cls.__name__, _cls.__qualname__ = "tf2", _name, _name  # tracebacks read as real tf's


def _strip(frame: str) -> str:
    return frame[1:] if frame.startswith("/") else frame


def _ns(stamp) -> int:
    return stamp.secs * _NS + stamp.nsecs


def _secs(t_ns: int) -> str:
    return "%.9f" % (t_ns / 1e9)


def _qmul(a, b):
    """Quaternion product a * b, with tf2's (Bullet's) operation order."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by + ay * bw + az * bx - ax * bz,
            aw * bz + az * bw + ax * by - ay * bx, aw * bw - ax * bx - ay * by - az * bz)


def _rotate(q, v):
    """tf2's quatRotate: (q * v) * q^-1, with v a pure vector."""
    x, y, z, w = q
    vx, vy, vz = v
    p = (w * vx + y * vz - z * vy, w * vy + z * vx - x * vz, w * vz + x * vy - y * vx, -x * vx - y * vy - z * vz)
    r = _qmul(p, (-x, -y, -z, w))
    return (r[0], r[1], r[2])


def _accumulate(edge, accum):
    """One step up the tree: the edge's transform applied after accum (tf2's TransformAccum::accum)."""
    translation, rotation = edge
    moved = _rotate(rotation, accum[0])
    return ((moved[0] + translation[0], moved[1] + translation[1], moved[2] + translation[2]),
            _qmul(rotation, accum[1]))


def _slerp(q0, q1, t):
    """tf2's Quaternion::slerp (shortest path)."""
    dot = sum(a * b for a, b in zip(q0, q1))
    norms = math.sqrt(sum(a * a for a in q0) * sum(b * b for b in q1))
    theta = (math.acos(-dot / norms) if dot < 0 else math.acos(dot / norms))
    if theta == 0:
        return tuple(q0)
    d = 1.0 / math.sin(theta)
    s0 = math.sin((1.0 - t) * theta)
    s1 = math.sin(t * theta)
    sign = -1.0 if dot < 0 else 1.0
    return tuple((a * s0 + sign * b * s1) * d for a, b in zip(q0, q1))


def _interpolate(a, b, ratio):
    translation = tuple(a[0][i] + (b[0][i] - a[0][i]) * ratio for i in range(3))
    return translation, _slerp(a[1], b[1], ratio)


class Transformer:
    """A buffer of timestamped parent->child transforms with tf's lookup semantics (time 0 = latest common)."""

    def __init__(self, interpolate=True, cache_time=None):
        self._interpolate = interpolate
        self._cache_ns = _ns(cache_time) if cache_time is not None else 10 * _NS
        self._parents: dict[str, str] = {}
        self._samples: dict[str, list] = {}  # child -> [(t_ns, translation, rotation)] in time order
        self._static: set[str] = set()
        self._lock = threading.Lock()

    def setTransform(self, transform, authority="default_authority") -> None:
        """Store a geometry_msgs/TransformStamped."""
        self._store(transform, static=False)

    def _store(self, transform, static: bool) -> None:
        child = _strip(transform.child_frame_id)
        tr, rot = transform.transform.translation, transform.transform.rotation
        if abs(rot.x * rot.x + rot.y * rot.y + rot.z * rot.z + rot.w * rot.w - 1.0) >= 1e-2:
            return  # tf2 ignores transforms with a denormalised quaternion
        sample = (_ns(transform.header.stamp), (tr.x, tr.y, tr.z), (rot.x, rot.y, rot.z, rot.w))
        with self._lock:
            self._parents[child] = _strip(transform.header.frame_id)
            if static:
                self._static.add(child)
                self._samples[child] = [sample]
                return
            samples = self._samples.setdefault(child, [])
            samples.append(sample)
            samples.sort(key=lambda s: s[0])
            cutoff = samples[-1][0] - self._cache_ns
            while samples and samples[0][0] < cutoff:
                samples.pop(0)

    def clear(self) -> None:
        with self._lock:
            self._parents.clear()
            self._samples.clear()
            self._static.clear()

    def frameExists(self, frame_id) -> bool:
        return _strip(frame_id) in self._parents

    def getFrameStrings(self) -> list:
        return list(self._parents)

    def allFramesAsString(self) -> str:
        return "".join("Frame %s exists with parent %s.\n" % (c, p) for c, p in self._parents.items())

    def _known(self, frame: str) -> bool:
        return frame in self._parents or frame in self._parents.values()

    def _chain(self, frame: str) -> list[str]:
        chain = [frame]
        while chain[-1] in self._parents and len(chain) < 1000:
            chain.append(self._parents[chain[-1]])
        return chain

    def _path(self, target: str, source: str, argument: str = "lookupTransform"):
        """The frames from source up to the common ancestor, and from target up to it."""
        for name, frame in (("target_frame", target), ("source_frame", source)):
            if not self._known(frame):
                raise LookupException('"%s" passed to %s argument %s does not exist. ' % (frame, argument, name))
        up_source, up_target = self._chain(source), self._chain(target)
        common = next((f for f in up_source if f in up_target), None)
        if common is None:
            raise ConnectivityException(
                "Could not find a connection between '%s' and '%s' because they are not part of the same tree."
                "Tf has two or more unconnected trees." % (target, source))
        return up_source[:up_source.index(common)], up_target[:up_target.index(common)]

    def _latest_common(self, frames: list[str]) -> int:
        dynamic = [self._samples[f][-1][0] for f in frames if f not in self._static]
        return min(dynamic) if dynamic else 0

    def _edge(self, child: str, t_ns: int, target: str, source: str):
        samples = self._samples[child]
        if child in self._static or t_ns == 0:
            return samples[-1][1:]
        if len(samples) == 1:
            if samples[0][0] == t_ns:
                return samples[0][1:]
            raise ExtrapolationException(
                "Lookup would require extrapolation at time %s, but only time %s is in the buffer, when looking up "
                "transform from frame [%s] to frame [%s]" % (_secs(t_ns), _secs(samples[0][0]), source, target))
        first, last = samples[0][0], samples[-1][0]
        if t_ns < first:
            raise ExtrapolationException(
                "Lookup would require extrapolation %ss into the past.  Requested time %s but the earliest data is "
                "at time %s, when looking up transform from frame [%s] to frame [%s]"
                % (_secs(first - t_ns), _secs(t_ns), _secs(first), source, target))
        if t_ns > last:
            raise ExtrapolationException(
                "Lookup would require extrapolation %ss into the future.  Requested time %s but the latest data is "
                "at time %s, when looking up transform from frame [%s] to frame [%s]"
                % (_secs(t_ns - last), _secs(t_ns), _secs(last), source, target))
        for before, after in zip(samples, samples[1:]):
            if before[0] <= t_ns <= after[0]:
                if t_ns == before[0] or not self._interpolate:
                    return before[1:]
                if t_ns == after[0]:
                    return after[1:]
                ratio = ((t_ns - before[0]) / 1e9) / ((after[0] - before[0]) / 1e9)
                return _interpolate(before[1:], after[1:], ratio)
        return samples[-1][1:]

    def _lookup(self, target: str, source: str, time):
        return self._lookup_at(target, source, time)[1:]

    def _lookup_at(self, target: str, source: str, time):
        """(time used in ns, translation, rotation): time 0 means the latest time all frames on the path share."""
        target, source = _strip(target), _strip(source)
        with self._lock:
            t_ns = _ns(time)
            if target == source:
                return t_ns, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)
            from_source, from_target = self._path(target, source)
            if t_ns == 0:
                t_ns = self._latest_common(from_source + from_target)
            identity = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
            up, down = identity, identity  # source -> common ancestor, target -> common ancestor
            for frame in from_source:
                up = _accumulate(self._edge(frame, t_ns, target, source), up)
            for frame in from_target:
                down = _accumulate(self._edge(frame, t_ns, target, source), down)
        if not from_target:
            return (t_ns, *up)
        inverse = (-down[1][0], -down[1][1], -down[1][2], down[1][3])
        back = _rotate(inverse, (-down[0][0], -down[0][1], -down[0][2]))
        if not from_source:
            return t_ns, back, inverse
        moved = _rotate(inverse, up[0])
        return t_ns, (moved[0] + back[0], moved[1] + back[1], moved[2] + back[2]), _qmul(inverse, up[1])

    def lookupTransform(self, target_frame, source_frame, time):
        """([x, y, z], [qx, qy, qz, qw]) taking source_frame coordinates into target_frame at time."""
        translation, rotation = self._lookup(target_frame, source_frame, time)
        return [float(v) for v in translation], [float(v) for v in rotation]

    def canTransform(self, target_frame, source_frame, time):
        """1 when lookupTransform would succeed, else 0 (tf returns ints)."""
        try:
            self._lookup(target_frame, source_frame, time)
        except Exception:
            return 0
        return 1

    def getLatestCommonTime(self, source_frame, target_frame):
        import rospy
        target, source = _strip(target_frame), _strip(source_frame)
        with self._lock:
            from_source, from_target = self._path(target, source, "getLatestCommonTime")
            t_ns = self._latest_common(from_source + from_target)
        return rospy.Time(t_ns // _NS, t_ns % _NS)

    def fromTranslationRotation(self, translation, rotation):
        """4x4 matrix of a translation and (x, y, z, w) rotation."""
        return transformations.concatenate_matrices(transformations.translation_matrix(translation),
                                                    transformations.quaternion_matrix(rotation))

    def asMatrix(self, target_frame, hdr):
        translation, rotation = self.lookupTransform(target_frame, hdr.frame_id, hdr.stamp)
        return self.fromTranslationRotation(translation, rotation)

    def _transformed(self, target_frame, stamped, point, quaternion=None, translate=True):
        translation, rotation = self._lookup(target_frame, stamped.header.frame_id, stamped.header.stamp)
        moved = _rotate(rotation, point)
        if translate:
            moved = tuple(moved[i] + translation[i] for i in range(3))
        return moved, (_qmul(rotation, quaternion) if quaternion is not None else None)

    def transformPoint(self, target_frame, ps):
        """A geometry_msgs/PointStamped expressed in target_frame."""
        from geometry_msgs.msg import PointStamped
        (x, y, z), _ = self._transformed(target_frame, ps, (ps.point.x, ps.point.y, ps.point.z))
        out = PointStamped()
        out.header.stamp, out.header.frame_id = ps.header.stamp, target_frame
        out.point.x, out.point.y, out.point.z = x, y, z
        return out

    def transformVector3(self, target_frame, v3s):
        """A geometry_msgs/Vector3Stamped rotated into target_frame."""
        from geometry_msgs.msg import Vector3Stamped
        (x, y, z), _ = self._transformed(target_frame, v3s, (v3s.vector.x, v3s.vector.y, v3s.vector.z),
                                         translate=False)
        out = Vector3Stamped()
        out.header.stamp, out.header.frame_id = v3s.header.stamp, target_frame
        out.vector.x, out.vector.y, out.vector.z = x, y, z
        return out

    def transformQuaternion(self, target_frame, ps):
        """A geometry_msgs/QuaternionStamped expressed in target_frame."""
        from geometry_msgs.msg import QuaternionStamped
        q = ps.quaternion
        _, rotated = self._transformed(target_frame, ps, (0.0, 0.0, 0.0), (q.x, q.y, q.z, q.w))
        out = QuaternionStamped()
        out.header.stamp, out.header.frame_id = ps.header.stamp, target_frame
        out.quaternion.x, out.quaternion.y, out.quaternion.z, out.quaternion.w = rotated
        return out

    def transformPose(self, target_frame, ps):
        """A geometry_msgs/PoseStamped expressed in target_frame."""
        from geometry_msgs.msg import PoseStamped
        p, q = ps.pose.position, ps.pose.orientation
        (x, y, z), rotated = self._transformed(target_frame, ps, (p.x, p.y, p.z), (q.x, q.y, q.z, q.w))
        out = PoseStamped()
        out.header.stamp, out.header.frame_id = ps.header.stamp, target_frame
        out.pose.position.x, out.pose.position.y, out.pose.position.z = x, y, z
        o = out.pose.orientation
        o.x, o.y, o.z, o.w = rotated
        return out


TransformerROS = Transformer


class TransformListener(Transformer):
    """A Transformer filled from /tf and /tf_static through rospy subscribers."""

    def __init__(self, interpolate=True, cache_time=None, *args, **kwargs):
        import rospy
        from tf2_msgs.msg import TFMessage
        super().__init__(interpolate, cache_time)
        self._subscribers = [rospy.Subscriber("/tf", TFMessage, self._on_tf, queue_size=None),
                             rospy.Subscriber("/tf_static", TFMessage, self._on_tf_static, queue_size=None)]

    def _on_tf(self, msg) -> None:
        for transform in msg.transforms:
            self._store(transform, static=False)

    def _on_tf_static(self, msg) -> None:
        for transform in msg.transforms:
            self._store(transform, static=True)

    def waitForTransform(self, target_frame, source_frame, time, timeout, polling_sleep_duration=None):
        """Block (in ROS time) until the transform is available; raise tf.Exception after timeout."""
        import rospy
        poll = polling_sleep_duration if polling_sleep_duration is not None else rospy.Duration(0.01)
        deadline = rospy.Time.now() + timeout
        while True:
            try:
                self._lookup(target_frame, source_frame, time)
                return
            except Exception as error:
                if rospy.Time.now() >= deadline or rospy.is_shutdown():
                    raise Exception(str(error)) from None
            rospy.sleep(poll)


class TransformBroadcaster:
    """Publishes transforms as tf2_msgs/TFMessage on /tf."""

    def __init__(self, queue_size=100):
        import rospy
        from tf2_msgs.msg import TFMessage
        self._message = TFMessage
        self.pub_tf = rospy.Publisher("/tf", TFMessage, queue_size=queue_size)

    def sendTransform(self, translation, rotation, time, child, parent):
        """Publish parent -> child at time; rotation is (x, y, z, w)."""
        from geometry_msgs.msg import TransformStamped
        t = TransformStamped()
        t.header.frame_id = parent
        t.header.stamp = time
        t.child_frame_id = child
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = translation[:3]
        r = t.transform.rotation
        r.x, r.y, r.z, r.w = rotation[:4]
        self.sendTransformMessage(t)

    def sendTransformMessage(self, transform):
        """Publish one geometry_msgs/TransformStamped (or a list of them)."""
        transforms = transform if isinstance(transform, list) else [transform]
        self.pub_tf.publish(self._message(transforms))
