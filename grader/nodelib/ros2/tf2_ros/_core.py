"""tf2's transform tree for ROS 2's tf2_ros: per-frame samples, lookups through the common ancestor, linear/slerp
interpolation, and tf2's error texts."""
from __future__ import annotations

import math

_NS = 1_000_000_000


class TransformException(Exception):
    """tf2.TransformException: the base of every lookup error."""


class LookupException(TransformException):
    pass


class ConnectivityException(TransformException):
    pass


class ExtrapolationException(TransformException):
    pass


class InvalidArgumentException(TransformException):
    pass


class TimeoutException(TransformException):
    pass


for _cls in (TransformException, LookupException, ConnectivityException, ExtrapolationException,
             InvalidArgumentException, TimeoutException):
    _cls.__module__ = "tf2"  # real tf2_ros re-exports tf2_py's classes, whose tracebacks say tf2.LookupException


def _qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def _rotate(q, v):
    x, y, z, w = _qmul(_qmul(q, (v[0], v[1], v[2], 0.0)), (-q[0], -q[1], -q[2], q[3]))
    return (x, y, z)


def _compose(parent, child):
    """parent ∘ child for (translation, rotation) pairs."""
    moved = _rotate(parent[1], child[0])
    return ((parent[0][0] + moved[0], parent[0][1] + moved[1], parent[0][2] + moved[2]), _qmul(parent[1], child[1]))


def _inverse(tf):
    q = (-tf[1][0], -tf[1][1], -tf[1][2], tf[1][3])
    t = _rotate(q, tf[0])
    return ((-t[0], -t[1], -t[2]), q)


def _slerp(a, b, ratio):
    dot = sum(x * y for x, y in zip(a, b))
    if dot < 0:
        b, dot = tuple(-x for x in b), -dot
    if dot > 0.9995:
        q = tuple(x + ratio * (y - x) for x, y in zip(a, b))
    else:
        theta = math.acos(dot)
        s = math.sin(theta)
        q = tuple((math.sin((1 - ratio) * theta) * x + math.sin(ratio * theta) * y) / s for x, y in zip(a, b))
    n = math.sqrt(sum(x * x for x in q))
    return tuple(x / n for x in q)


def _secs(ns: int) -> str:
    return "%.6f" % (ns / _NS)


class BufferCore:
    """Samples per child frame (a parent and time-ordered (t_ns, translation, rotation)), static or dynamic."""

    def __init__(self, cache_time_ns: int = 10 * _NS) -> None:
        self._cache_ns = cache_time_ns
        self._parents: dict[str, str] = {}
        self._samples: dict[str, list] = {}
        self._static: set[str] = set()

    def set_transform(self, transform, authority: str, static: bool = False) -> bool:
        child = transform.child_frame_id.lstrip("/")
        parent = transform.header.frame_id.lstrip("/")
        tr, rot = transform.transform.translation, transform.transform.rotation
        if not child or not parent or child == parent:
            return False
        if abs(rot.x * rot.x + rot.y * rot.y + rot.z * rot.z + rot.w * rot.w - 1.0) >= 1e-2:
            return False
        stamp = transform.header.stamp.sec * _NS + transform.header.stamp.nanosec
        sample = (stamp, (tr.x, tr.y, tr.z), (rot.x, rot.y, rot.z, rot.w))
        self._parents[child] = parent
        if static:
            self._static.add(child)
            self._samples[child] = [sample]
            return True
        samples = self._samples.setdefault(child, [])
        samples.append(sample)
        samples.sort(key=lambda s: s[0])
        cutoff = samples[-1][0] - self._cache_ns
        while samples and samples[0][0] < cutoff:
            samples.pop(0)
        return True

    def clear(self) -> None:
        self._parents.clear()
        self._samples.clear()
        self._static.clear()

    def frames(self) -> list[str]:
        return sorted(set(self._parents) | set(self._parents.values()))

    def all_frames_as_string(self) -> str:
        return "".join(f"Frame {c} exists with parent {p}.\n" for c, p in self._parents.items())

    def _chain(self, frame: str) -> list[str]:
        chain = [frame]
        while chain[-1] in self._parents and len(chain) < 1000:
            chain.append(self._parents[chain[-1]])
        return chain

    def _path(self, target: str, source: str):
        known = set(self._parents) | set(self._parents.values())
        for name, frame in (("target_frame", target), ("source_frame", source)):
            if frame not in known:
                raise LookupException(f'"{frame}" passed to lookupTransform argument {name} does not exist. ')
        up_source, up_target = self._chain(source), self._chain(target)
        common = next((f for f in up_source if f in up_target), None)
        if common is None:
            raise ConnectivityException(
                f"Could not find a connection between '{target}' and '{source}' because they are not part of the "
                "same tree.Tf has two or more unconnected trees.")
        return up_source[:up_source.index(common)], up_target[:up_target.index(common)]

    def _edge(self, child: str, t_ns: int, target: str, source: str):
        samples = self._samples[child]
        if child in self._static or t_ns == 0:
            return samples[-1][1:]
        first, last = samples[0][0], samples[-1][0]
        if len(samples) == 1 and first != t_ns:
            raise ExtrapolationException(
                f"Lookup would require extrapolation at time {_secs(t_ns)}, but only time {_secs(first)} is in the "
                f"buffer, when looking up transform from frame [{source}] to frame [{target}]")
        if t_ns < first:
            raise ExtrapolationException(
                f"Lookup would require extrapolation {_secs(first - t_ns)}s into the past.  Requested time "
                f"{_secs(t_ns)} but the earliest data is at time {_secs(first)}, when looking up transform from "
                f"frame [{source}] to frame [{target}]")
        if t_ns > last:
            raise ExtrapolationException(
                f"Lookup would require extrapolation {_secs(t_ns - last)}s into the future.  Requested time "
                f"{_secs(t_ns)} but the latest data is at time {_secs(last)}, when looking up transform from frame "
                f"[{source}] to frame [{target}]")
        for before, after in zip(samples, samples[1:]):
            if before[0] <= t_ns <= after[0]:
                if t_ns == before[0]:
                    return before[1:]
                ratio = (t_ns - before[0]) / (after[0] - before[0])
                tr = tuple(a + ratio * (b - a) for a, b in zip(before[1], after[1]))
                return tr, _slerp(before[2], after[2], ratio)
        return samples[-1][1:]

    def lookup(self, target: str, source: str, t_ns: int):
        """(time used, translation, rotation) taking source coordinates into target; t_ns 0 = latest common."""
        target, source = target.lstrip("/"), source.lstrip("/")
        if target == source:
            return t_ns, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)
        from_source, from_target = self._path(target, source)
        if t_ns == 0:
            dynamic = [self._samples[f][-1][0] for f in from_source + from_target if f not in self._static]
            t_ns = min(dynamic) if dynamic else 0
        identity = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
        up = down = identity
        for frame in from_source:
            up = _compose(self._edge(frame, t_ns, target, source), up)
        for frame in from_target:
            down = _compose(self._edge(frame, t_ns, target, source), down)
        result = _compose(_inverse(down), up)
        return t_ns, result[0], result[1]
