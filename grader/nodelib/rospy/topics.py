"""rospy.Publisher and rospy.Subscriber over the grader channel, with one callback thread per topic."""
from __future__ import annotations

import io
import itertools
import re
import traceback
import zlib
import warnings
from collections import deque

import genpy
import rosgrade_channel as ch
from rosgrade_node import excepthook, runtime

from . import core, names, rostime
from .exceptions import ROSException, ROSSerializationException
from .msg import args_kwds_to_message

# Handles are the node's ids for ADVERTISE/SUBSCRIBE/PUBLISH/DELIVER/UNREGISTER.
_handle_ids = itertools.count(1)
# Topics created before init_node: rospy registers them with the master at init; we announce them then.
_pending: list[Topic] = []
_open: dict[int, Topic] = {}
_topic_threads: dict[str, _TopicThread] = {}
# The world's topics are published by Gazebo; received messages carry this caller id.
_PUBLISHER_CALLERID = "/gazebo"


def stable_repr(obj) -> str:
    """repr() with the memory address replaced by one derived from the object's name, so output is reproducible."""
    name = getattr(obj, "__qualname__", type(obj).__qualname__)
    address = 0x7F0000000000 + (zlib.crc32(name.encode()) << 4)
    return re.sub(r" at 0x[0-9a-fA-F]+", " at 0x%x" % address, repr(obj))


def _check_args(name, data_class) -> None:
    if not name or not isinstance(name, str):
        raise ValueError("topic name is not a non-empty string")
    if not isinstance(data_class, type):
        raise ValueError("data_class [%s] is not a class" % data_class)
    if not issubclass(data_class, genpy.Message):
        raise ValueError("data_class [%s] is not a message data class" % data_class.__name__)


class Topic:
    """What Publisher and Subscriber share: the resolved name, the message class and the channel handle."""

    def __init__(self, name: str, data_class: type, reg_type: str) -> None:
        _check_args(name, data_class)
        self.resolved_name = self.name = names.resolve_name(name)
        self.data_class = data_class
        self.type = data_class._type
        self.md5sum = data_class._md5sum
        self.reg_type = reg_type
        # Not None while registered (rospy's impl); publish() on an unregistered handle fails.
        self.impl: int | None = next(_handle_ids)
        self._announced = False

    def _register(self) -> None:
        if core.is_initialized():
            self._announce()
        else:
            _pending.append(self)

    def _announce(self) -> None:
        if core._shutdown_flag or self.impl is None:
            return
        kind = ch.ADVERTISE if self.reg_type == "pub" else ch.SUBSCRIBE
        runtime.link.send_json(kind, {"id": self.impl, "topic": self.resolved_name, "type": self.type,
                                      "md5sum": self.md5sum, "queue_size": self._queue_size(),
                                      "latch": self._latch()})
        self._announced = True
        _open[self.impl] = self

    def _queue_size(self) -> int | None:
        return None

    def _latch(self) -> bool:
        return False

    def _close(self) -> None:
        """Tell the grader the handle is gone (once)."""
        if self._announced:
            self._announced = False
            _open.pop(self.impl, None)
            runtime.link.send_json(ch.UNREGISTER, {"id": self.impl})
        if self in _pending:
            _pending.remove(self)

    def get_num_connections(self) -> int:
        """1 once the grader knows the topic (the world is taken to be connected), else 0."""
        return 1 if self._announced else 0

    def unregister(self) -> None:
        """Close the handle; further calls have no effect."""
        if self.impl is not None:
            self._close()
            self.impl = None


class Publisher(Topic):
    """Publishes messages to the grader. Serialization always runs (the robot always subscribes)."""

    def __init__(self, name, data_class, subscriber_listener=None, tcp_nodelay=False, latch=False, headers=None,
                 queue_size=None) -> None:
        super().__init__(name, data_class, "pub")
        self.latch = bool(latch)
        self.queue_size = queue_size
        if queue_size is None:
            warnings.warn("The publisher should be created with an explicit keyword argument 'queue_size'. "
                          "Please see http://wiki.ros.org/rospy/Overview/Publishers%20and%20Subscribers for more "
                          "information.", SyntaxWarning, stacklevel=2)
        self._register()

    def _queue_size(self) -> int | None:
        return self.queue_size if isinstance(self.queue_size, int) else None

    def _latch(self) -> bool:
        return self.latch

    def publish(self, *args, **kwds) -> None:
        """Publish a message, or build one from ``args``/``kwds``; silently dropped after shutdown."""
        if self.impl is None:
            raise ROSException("publish() to an unregistered() handle")
        if not core.is_initialized():
            raise ROSException("ROS node has not been initialized yet. Please call init_node() first")
        data = args_kwds_to_message(self.data_class, args, kwds)
        rostime.charge()
        if core._shutdown_flag or not self._announced:
            return None
        buff = io.BytesIO()
        try:
            data.serialize(buff)
        except genpy.SerializationError as exc:
            raise ROSSerializationException(str(exc)) from None
        runtime.link.send_message(ch.PUBLISH, self.impl, buff.getvalue())
        return None


class Subscriber(Topic):
    """Receives the grader's DELIVER frames; callbacks run in the topic's own thread, one message at a time."""

    def __init__(self, name, data_class, callback=None, callback_args=None, queue_size=None, buff_size=65536,
                 tcp_nodelay=False) -> None:
        super().__init__(name, data_class, "sub")
        if queue_size == -1:
            queue_size = None
        elif queue_size == 0:
            raise ROSException("queue size may not be set to zero")
        elif queue_size is not None and type(queue_size) is not int:
            raise ROSException("queue size must be an integer")
        self.queue_size = queue_size
        self.callback = callback
        self.callback_args = callback_args
        thread = _topic_threads.get(self.resolved_name)
        if thread is None:
            thread = _topic_threads[self.resolved_name] = _TopicThread(self.resolved_name)
        self._thread = thread
        runtime.scheduler.add_sink(self.impl, lambda data: thread.push(self, data))
        self._register()

    def _queue_size(self) -> int | None:
        return self.queue_size

    def _close(self) -> None:
        runtime.scheduler.remove_sink(self.impl)
        self._thread.drop(self)
        super()._close()

    def unregister(self) -> None:
        self.callback = self.callback_args = None
        super().unregister()

    def _dispatch(self, data: bytes) -> None:
        """Deserialize and run the callback; an exception is logged as rospy does and the node carries on."""
        if self.impl is None or core._shutdown_flag:
            return
        msg = self.data_class()
        msg.deserialize(data)
        msg._connection_header = {"callerid": _PUBLISHER_CALLERID, "md5sum": self.md5sum, "topic": self.resolved_name,
                                  "type": self.type, "message_definition": self.data_class._full_text,
                                  "latching": "0"}
        callback = self.callback
        if callback is None:
            return
        try:
            if self.callback_args is None:
                callback(msg)
            else:
                callback(msg, self.callback_args)
        except Exception:
            excepthook.report_current("callback")
            core.logerr("bad callback: %s\n%s" % (stable_repr(callback), traceback.format_exc()))


class _TopicThread:
    """The thread named after a topic that runs its subscribers' callbacks in delivery order."""

    def __init__(self, topic: str) -> None:
        self.queue: deque[tuple[Subscriber, bytes]] = deque()
        self.waiter = runtime.scheduler.spawn(topic, self._run, ready=self._has_messages)

    def _has_messages(self) -> bool:
        return bool(self.queue)

    def push(self, sub: Subscriber, data: bytes):
        """Queue a delivered message, dropping the subscriber's oldest beyond its queue_size."""
        self.queue.append((sub, data))
        if sub.queue_size is not None:
            mine = [entry for entry in self.queue if entry[0] is sub]
            for entry in mine[:len(mine) - sub.queue_size]:
                self.queue.remove(entry)
        return self.waiter

    def drop(self, sub: Subscriber) -> None:
        for entry in [e for e in self.queue if e[0] is sub]:
            self.queue.remove(entry)

    def _run(self) -> None:
        while True:
            while self.queue:
                sub, data = self.queue.popleft()
                sub._dispatch(data)
            runtime.scheduler.block(ready=self._has_messages)


def announce_pending() -> None:
    """init_node: tell the grader about topics created before it, in creation order."""
    for topic in list(_pending):
        _pending.remove(topic)
        topic._announce()


def close_all(reason: str) -> None:
    """Shutdown: every publisher and subscriber is closed (later publishes are dropped)."""
    for topic in list(_open.values()):
        topic._close()
