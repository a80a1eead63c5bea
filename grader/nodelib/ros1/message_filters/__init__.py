"""rosgrade's message_filters: Subscriber, Cache, TimeSynchronizer and ApproximateTimeSynchronizer of ROS 1 Noetic.

Filters pass messages on to the callbacks registered with them; the synchronizers call theirs with one message per
input once the inputs' header stamps match exactly (TimeSynchronizer) or lie within ``slop`` seconds
(ApproximateTimeSynchronizer), as the Python message_filters of Noetic do.
"""
from __future__ import annotations

import itertools
import threading
from functools import reduce

__all__ = ["ApproximateTimeSynchronizer", "Cache", "SimpleFilter", "Subscriber", "TimeSynchronizer"]


class SimpleFilter:
    """A source of messages for the callbacks registered with it."""

    def __init__(self) -> None:
        self.callbacks: dict = {}

    def registerCallback(self, cb, *args):
        """Call ``cb(msg..., *args)`` for every message; returns a handle for ``unregister``-style removal."""
        conn = len(self.callbacks)
        self.callbacks[conn] = (cb, args)
        return conn

    def signalMessage(self, *msg) -> None:
        for cb, args in list(self.callbacks.values()):
            cb(*(msg + args))


class Subscriber(SimpleFilter):
    """A rospy.Subscriber whose messages feed the filter chain (same arguments as rospy.Subscriber)."""

    def __init__(self, *args, **kwargs) -> None:
        import rospy
        super().__init__()
        self.topic = args[0]
        kwargs["callback"] = self.callback
        self.sub = rospy.Subscriber(*args, **kwargs)

    def callback(self, msg) -> None:
        self.signalMessage(msg)

    def getTopic(self):
        return self.sub.resolved_name

    def __getattr__(self, key):
        """Everything else (get_num_connections, unregister, ...) is the wrapped rospy.Subscriber's."""
        if key == "sub":
            raise AttributeError(key)
        return self.sub.__getattribute__(key)


def _stamp(msg, allow_headerless: bool):
    """A message's header stamp; ROS time now for a header-less one when allowed; None (with a warning) if not."""
    import rospy
    if hasattr(msg, "header") and hasattr(msg.header, "stamp"):
        return msg.header.stamp
    if not allow_headerless:
        rospy.logwarn("Cannot use message filters with non-stamped messages. Use the 'allow_headerless' "
                      "constructor option to auto-assign ROS time to headerless messages.")
        return None
    return rospy.Time.now()


class Cache(SimpleFilter):
    """Keeps the last ``cache_size`` messages of a filter, ordered by stamp, and passes each one on."""

    def __init__(self, f, cache_size=1, allow_headerless=False) -> None:
        super().__init__()
        self.connectInput(f)
        self.cache_size = cache_size
        self.cache_msgs: list = []
        self.cache_times: list = []
        self.allow_headerless = allow_headerless

    def connectInput(self, f) -> None:
        self.incoming_connection = f.registerCallback(self.add)

    def add(self, msg) -> None:
        stamp = _stamp(msg, self.allow_headerless)
        if stamp is None:
            return
        self.cache_msgs.append(msg)
        self.cache_times.append(stamp)
        if len(self.cache_msgs) > self.cache_size:
            del self.cache_msgs[0]
            del self.cache_times[0]
        self.signalMessage(msg)

    def getInterval(self, from_stamp, to_stamp) -> list:
        """Messages stamped in [from_stamp, to_stamp]."""
        assert from_stamp <= to_stamp
        return [m for m, t in zip(self.cache_msgs, self.cache_times) if from_stamp <= t <= to_stamp]

    def getElemAfterTime(self, stamp):
        """The oldest message stamped at or after ``stamp``, or None."""
        return next((m for m, t in zip(self.cache_msgs, self.cache_times) if t >= stamp), None)

    def getElemBeforeTime(self, stamp):
        """The newest message stamped at or before ``stamp``, or None."""
        before = [m for m, t in zip(self.cache_msgs, self.cache_times) if t <= stamp]
        return before[-1] if before else None

    def getLatestTime(self):
        return self.cache_times[-1] if self.cache_times else None

    getLastestTime = getLatestTime  # the old spelling, kept by Noetic

    def getOldestTime(self):
        return self.cache_times[0] if self.cache_times else None

    def getLast(self):
        """The oldest message stamped at the latest stamp, or None."""
        latest = self.getLatestTime()
        return None if latest is None else self.getElemAfterTime(latest)


class TimeSynchronizer(SimpleFilter):
    """Calls back with one message per input filter when all carry the same header stamp.

    ``reset`` (clear the queues when ROS time jumps back) changes nothing here: sim time never goes backwards.
    """

    def __init__(self, fs, queue_size, reset=False) -> None:
        super().__init__()
        self.connectInput(fs)
        self.queue_size = queue_size
        self.lock = threading.Lock()

    def connectInput(self, fs) -> None:
        self.queues = [{} for _ in fs]
        self.input_connections = [f.registerCallback(self.add, q, i) for i, (f, q) in enumerate(zip(fs, self.queues))]

    def add(self, msg, my_queue, my_queue_index=None) -> None:
        with self.lock:
            my_queue[msg.header.stamp] = msg
            while len(my_queue) > self.queue_size:
                del my_queue[min(my_queue)]
            common = reduce(set.intersection, [set(q) for q in self.queues])
            for t in sorted(common):
                msgs = [q[t] for q in self.queues]
                self.signalMessage(*msgs)
                for q in self.queues:
                    del q[t]


class ApproximateTimeSynchronizer(TimeSynchronizer):
    """Calls back with one message per input when their stamps all lie within ``slop`` seconds of each other."""

    def __init__(self, fs, queue_size, slop, allow_headerless=False, reset=False) -> None:
        import rospy
        super().__init__(fs, queue_size, reset)
        self.slop = rospy.Duration.from_sec(slop)
        self.allow_headerless = allow_headerless

    def add(self, msg, my_queue, my_queue_index=None) -> None:
        stamp = _stamp(msg, self.allow_headerless)
        if stamp is None:
            return
        with self.lock:
            my_queue[stamp] = msg
            while len(my_queue) > self.queue_size:
                del my_queue[min(my_queue)]
            others = self.queues if my_queue_index is None else \
                self.queues[:my_queue_index] + self.queues[my_queue_index + 1:]
            # For each other input, its stamps within slop of the new one, nearest first.
            candidates = []
            for queue in others:
                near = sorted(((s, abs(s - stamp)) for s in queue if abs(s - stamp) <= self.slop),
                              key=lambda pair: pair[1])
                if not near:
                    return
                candidates.append([s for s, _ in near])
            for combination in itertools.product(*candidates):
                chosen = list(combination)
                if my_queue_index is not None:
                    chosen.insert(my_queue_index, stamp)
                pairs = list(zip(self.queues, chosen))
                if max(chosen) - min(chosen) < self.slop and all(t in q for q, t in pairs):
                    self.signalMessage(*[q[t] for q, t in pairs])
                    for q, t in pairs:
                        del q[t]
                    break
