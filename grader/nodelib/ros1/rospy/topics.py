"""rospy.Publisher and rospy.Subscriber over the grader channel, with connection counts and one connection per topic."""
from __future__ import annotations

import io
import itertools
import re
import traceback
import zlib
import warnings

import genpy
import rosgrade_channel as ch
from rosgrade_node import excepthook, runtime

from . import core, names, rostime
from .exceptions import ROSException, ROSSerializationException
from .msg import args_kwds_to_message

# Handles are the node's ids for ADVERTISE/SUBSCRIBE/PUBLISH/UNREGISTER and for deliveries in BATCH frames.
_handle_ids = itertools.count(1)
# Handles created before init_node: rospy registers them with the master during init; we announce them then.
_pending: list[_Registration] = []
_open: dict[int, _Registration] = {}
_sub_impls: dict[str, _SubscriberImpl] = {}
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
    """What Publisher and Subscriber share: the resolved name and the message class."""

    def __init__(self, name: str, data_class: type, reg_type: str) -> None:
        _check_args(name, data_class)
        self.resolved_name = self.name = names.resolve_name(name)
        self.data_class = data_class
        self.type = data_class._type
        self.md5sum = data_class._md5sum
        self.reg_type = reg_type


class _Registration:
    """One channel handle (ADVERTISE/SUBSCRIBE ... UNREGISTER); announced at once, or at init_node if created before."""

    reg_type = "pub"

    def __init__(self, resolved_name: str, data_class: type) -> None:
        self.resolved_name = resolved_name
        self.data_class = data_class
        self.handle: int = next(_handle_ids)
        self.announced = False
        self.queue_size: int | None = None
        self.latch = False

    def register(self) -> None:
        if core.is_initialized() or core.is_initializing():
            self.announce()
        else:
            _pending.append(self)

    def announce(self) -> None:
        if core._shutdown_flag:
            return
        kind = ch.ADVERTISE if self.reg_type == "pub" else ch.SUBSCRIBE
        runtime.link.send_json(kind, {"id": self.handle, "topic": self.resolved_name, "type": self.data_class._type,
                                      "md5sum": self.data_class._md5sum, "queue_size": self.queue_size,
                                      "latch": self.latch})
        self.announced = True
        _open[self.handle] = self

    def close(self) -> None:
        """Tell the grader the handle is gone (once)."""
        if self.announced:
            self.announced = False
            _open.pop(self.handle, None)
            runtime.link.send_json(ch.UNREGISTER, {"id": self.handle})
        if self in _pending:
            _pending.remove(self)

    def num_connections(self) -> int:
        """How many nodes the grader has connected this handle to (the robot's base counts as one)."""
        return runtime.scheduler.connections.get(self.handle, 0) if self.announced else 0


class Publisher(Topic):
    """Publishes messages to the grader; bad field values raise only while a subscriber is connected (rospy
    serializes only then)."""

    def __init__(self, name, data_class, subscriber_listener=None, tcp_nodelay=False, latch=False, headers=None,
                 queue_size=None) -> None:
        super().__init__(name, data_class, "pub")
        self.latch = bool(latch)
        self.queue_size = queue_size
        if queue_size is None:
            warnings.warn("The publisher should be created with an explicit keyword argument 'queue_size'. "
                          "Please see http://wiki.ros.org/rospy/Overview/Publishers%20and%20Subscribers for more "
                          "information.", SyntaxWarning, stacklevel=2)
        self.impl: _Registration | None = _Registration(self.resolved_name, data_class)
        self.impl.queue_size = queue_size if isinstance(queue_size, int) else None
        self.impl.latch = self.latch
        self.impl.register()

    def get_num_connections(self) -> int:
        """The number of subscribing nodes connected: 0 until the first has connected (about 50 ms)."""
        return self.impl.num_connections() if self.impl is not None else 0

    def unregister(self) -> None:
        """Close the handle; further calls have no effect. The node's own subscription loses its connection from
        this node once no publisher of it on the topic is left."""
        if self.impl is not None:
            self.impl.close()
            self.impl = None
            own = _sub_impls.get(self.resolved_name)
            if own is not None and not any(reg.reg_type == "pub" and reg.resolved_name == self.resolved_name
                                           for reg in _open.values()):
                own.drop_connection(names.get_caller_id())

    def publish(self, *args, **kwds) -> None:
        """Publish a message, or build one from ``args``/``kwds``; silently dropped after shutdown."""
        if self.impl is None:
            raise ROSException("publish() to an unregistered() handle")
        if not core.is_initialized():
            raise ROSException("ROS node has not been initialized yet. Please call init_node() first")
        data = args_kwds_to_message(self.data_class, args, kwds)
        rostime.charge()
        if core._shutdown_flag or not self.impl.announced:
            return None
        buff = io.BytesIO()
        try:
            data.serialize(buff)
        except genpy.SerializationError as exc:
            if not self.impl.num_connections():
                return None  # rospy never serializes for a topic nobody is connected to
            raise ROSSerializationException(str(exc)) from None
        runtime.link.send_message(ch.PUBLISH, self.impl.handle, buff.getvalue())
        return None


class Subscriber(Topic):
    """A callback on a topic; every Subscriber on one topic in a node shares that topic's ``_SubscriberImpl``: its
    message class and its connections, one per publisher, each with its own queue and thread."""

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
        impl = _sub_impls.get(self.resolved_name)
        if impl is None:
            impl = _sub_impls[self.resolved_name] = _SubscriberImpl(self.resolved_name, data_class)
        self.impl: _SubscriberImpl | None = impl
        impl.acquire(self)

    def get_num_connections(self) -> int:
        """The number of publishing nodes connected to this topic's connection."""
        return self.impl.num_connections() if self.impl is not None else 0

    def unregister(self) -> None:
        """Stop receiving; further calls have no effect."""
        if self.impl is not None:
            self.impl.release(self)
            self.impl = None
            self.callback = self.callback_args = None


class _SubscriberImpl(_Registration):
    """The node's subscription to one topic: registered while any Subscriber uses it. The first subscriber's class
    decodes the messages; the last queue_size given wins for connections made after it (as in rospy)."""

    reg_type = "sub"

    def __init__(self, resolved_name: str, data_class: type) -> None:
        super().__init__(resolved_name, data_class)
        self.subscribers: list[Subscriber] = []
        self.connections: dict[str, _Connection] = {}

    def acquire(self, sub: Subscriber) -> None:
        """Add a subscriber; like rospy's add_callback, it gets each latched connection's last message at once, in
        the caller's thread."""
        if not self.subscribers:
            if self.announced or self in _pending:
                self.close()
            self.handle = next(_handle_ids)
            self.data_class = sub.data_class
            self.queue_size = None
            runtime.scheduler.add_sink(self.handle, self._push, sources=True)
            self.subscribers.append(sub)
            self._set_queue_size(sub.queue_size)
            self.register()
            return
        self._set_queue_size(sub.queue_size)
        self.subscribers.append(sub)
        for connection in list(self.connections.values()):
            if connection.latch is not None:
                _invoke_callback(sub, connection.latch)

    def _set_queue_size(self, queue_size: int | None) -> None:
        if queue_size is not None:
            self.queue_size = queue_size

    def release(self, sub: Subscriber) -> None:
        if sub in self.subscribers:
            self.subscribers.remove(sub)
        if not self.subscribers:
            self.close()

    def close(self) -> None:
        runtime.scheduler.remove_sink(self.handle)
        for connection in self.connections.values():
            connection.closed = True
        self.connections = {}
        super().close()

    def drop_connection(self, callerid: str) -> None:
        """The publisher of ``callerid`` is gone: its connection's thread ends and its latched message with it."""
        connection = self.connections.pop(callerid, None)
        if connection is not None:
            connection.closed = True

    def _push(self, data: bytes, source: tuple[str, bool] | None):
        """A delivered message arrives on its publisher's connection, made when the first one arrives."""
        callerid, latched = source or (_PUBLISHER_CALLERID, False)
        connection = self.connections.get(callerid)
        if connection is None:
            connection = self.connections[callerid] = _Connection(self, callerid, latched)
        connection.pending.append(data)
        return connection.waiter

    def receive(self, msgs: list) -> None:
        """rospy's receive_callback: the callbacks registered when a read ends are called for each message read;
        its receive loop swallows anything that gets past the per-callback ``except Exception`` (sys.exit() in a
        callback) and reads on."""
        subscribers = list(self.subscribers)
        try:
            for msg in msgs:
                for sub in subscribers:
                    _invoke_callback(sub, msg)
        except BaseException:  # noqa: BLE001 - what rospy's receive loop does
            pass


class _Connection:
    """One publisher's connection to a subscription (rospy's TCPROSSub): its own thread, named after the topic, reads
    everything received since its last read, keeps the last ``queue_size`` (fixed when the connection was made) and
    runs the callbacks on them; a latched connection keeps the last message it read for later subscribers."""

    def __init__(self, impl: _SubscriberImpl, callerid: str, latched: bool) -> None:
        self.impl = impl
        self.queue_size = impl.queue_size
        self.header = {"callerid": callerid, "md5sum": impl.data_class._md5sum, "topic": impl.resolved_name,
                       "type": impl.data_class._type, "message_definition": impl.data_class._full_text,
                       "latching": "1" if latched else "0"}
        self.latched = latched
        self.latch = None
        self.pending: list[bytes] = []  # received, not read yet (rospy's socket buffer)
        self.closed = False
        self.waiter = runtime.scheduler.spawn(impl.resolved_name, self._run, ready=self._readable)

    def _readable(self) -> bool:
        return bool(self.pending) or self.closed

    def _run(self) -> None:
        while not self.closed:
            buffers, self.pending = self.pending, []
            if self.queue_size is not None:
                buffers = buffers[-self.queue_size:]
            if buffers and not core._shutdown_flag:
                msgs = [self._message(data) for data in buffers]
                if self.latched:
                    self.latch = msgs[-1]
                self.impl.receive(msgs)
            runtime.scheduler.block(ready=self._readable)

    def _message(self, data: bytes):
        msg = self.impl.data_class()
        msg.deserialize(data)
        msg._connection_header = self.header
        return msg


def _invoke_callback(sub: Subscriber, msg) -> None:
    """Run one callback; an exception is logged as rospy does and the node carries on."""
    callback = sub.callback
    if callback is None:
        return
    try:
        if sub.callback_args is None:
            callback(msg)
        else:
            callback(msg, sub.callback_args)
    except Exception:
        if core._shutdown_flag:
            return
        excepthook.report_current("callback")
        core.logerr("bad callback: %s\n%s" % (stable_repr(callback), traceback.format_exc()))


def announce_pending() -> None:
    """init_node: tell the grader about topics created before it, in creation order."""
    for registration in list(_pending):
        _pending.remove(registration)
        registration.announce()


def close_all(reason: str) -> None:
    """Shutdown: every publisher and subscriber is closed (later publishes are dropped)."""
    for registration in list(_open.values()):
        registration.close()
