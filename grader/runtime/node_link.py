"""The grader's side of one node: reads and validates its frames, tracks its topics, sends it time and messages.

Everything a node sends is untrusted data: frames are size-capped, JSON fields are type-checked, and message bytes
must decode exactly as the declared type before anything is recorded or reaches the robot.
"""
from __future__ import annotations

import select
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field

from grader.nodelib import rosgrade_channel as ch
from grader.recording import MessageCatalog, RecordingError


class ProtocolViolation(Exception):
    """The node sent something that is not a valid frame; it is stopped with this message."""


class NodeSilent(Exception):
    """The node ran longer than allowed without yielding to the grader."""


class NodeExited(Exception):
    """The node's end of the channel closed."""


@dataclass
class Endpoint:
    """A publisher or subscriber the node registered."""

    ident: int
    topic: str
    type: str
    md5sum: str
    queue_size: int | None
    latch: bool
    registered_ns: int
    count: int = 0
    closed: bool = False
    dropped_before_connect: int = 0


@dataclass
class Publication:
    endpoint: Endpoint
    data: bytes


@dataclass
class LogLine:
    level: int
    msg: str
    name: str
    file: str
    function: str
    line: int


@dataclass
class OutputLine:
    stream: int
    text: str


@dataclass
class NodeState:
    """What the grader knows about a node between frames."""

    name: str | None = None
    init_ns: int | None = None
    disable_signals: bool = False
    publishers: dict[int, Endpoint] = field(default_factory=dict)
    subscribers: dict[int, Endpoint] = field(default_factory=dict)
    exception: dict | None = None  # the uncaught exception that ended the node, if any
    caught: list[dict] = field(default_factory=list)  # exceptions rospy printed and carried on from (callbacks, hooks)
    output_bytes: int = 0
    output_truncated: bool = False
    stderr_tail: deque = field(default_factory=lambda: deque(maxlen=4))  # last lines, for start-up failures


_LOG_LEVELS = {1, 2, 4, 8, 16}


def _field(obj: dict, key: str, kind: type | tuple[type, ...], optional: bool = False):
    value = obj.get(key)
    if value is None and optional:
        return None
    if not isinstance(value, kind) or isinstance(value, bool) and kind is int:
        raise ProtocolViolation(f"frame field {key!r} is missing or not {getattr(kind, '__name__', kind)}")
    return value


def _topic(value: str) -> str:
    if not value.startswith("/") or len(value) > 256 or any(c.isspace() for c in value):
        raise ProtocolViolation(f"invalid topic name {value[:80]!r}")
    return value


class NodeLink:
    """One node's channel, seen from the grader."""

    def __init__(self, read_fd: int, write_fd: int, catalog: MessageCatalog, silent_wall_s: float,
                 output_cap: int) -> None:
        self._reader = ch.FrameReader(read_fd, ch.NODE_KINDS, before_read=self._wait_readable)
        self._write_fd = write_fd
        self._catalog = catalog
        self._silent_wall_s = silent_wall_s
        self._output_cap = output_cap
        self._deadline = 0.0
        self._partial = {1: bytearray(), 2: bytearray()}
        self.state = NodeState()

    # -- reading -----------------------------------------------------------------------------------------------
    def _wait_readable(self) -> None:
        remaining = self._deadline - time.monotonic()
        if remaining <= 0 or not select.select([self._reader.fd], [], [], remaining)[0]:
            raise NodeSilent(f"did not yield to the grader for {self._silent_wall_s:g} s of wall time")

    def _read(self) -> tuple[int, bytes]:
        try:
            return self._reader.read()
        except ch.ChannelError as exc:
            if str(exc) == "channel closed":
                raise NodeExited() from None
            raise ProtocolViolation(str(exc)) from None

    def handshake(self, start: dict) -> dict:
        """Wait for HELLO, answer START; returns the HELLO payload."""
        self._deadline = time.monotonic() + self._silent_wall_s
        kind, payload = self._read()
        if kind != ch.HELLO:
            raise ProtocolViolation(f"expected HELLO first, got {ch.KIND_NAMES.get(kind, kind)}")
        hello = self._json(payload)
        if hello.get("protocol") != ch.PROTOCOL:
            raise ProtocolViolation(f"protocol {hello.get('protocol')!r} is not {ch.PROTOCOL}")
        self._send(ch.encode_json(ch.START, start))
        return hello

    def run_until_wait(self, t_ns: int, sink: Callable[[object], None]) -> int | None:
        """Read frames until the node yields, passing each event at t_ns to sink; returns wake_ns or None."""
        self._deadline = time.monotonic() + self._silent_wall_s
        while True:
            kind, payload = self._read()
            if kind == ch.WAIT:
                wake = self._json(payload).get("wake_ns")
                if wake is not None and (not isinstance(wake, int) or isinstance(wake, bool)):
                    raise ProtocolViolation("WAIT wake_ns is not an integer")
                # A wake-up in the past would let a node stall the world forever: it costs at least one quantum.
                return max(wake, t_ns + ch.CALL_QUANTUM_NS) if wake is not None else None
            event = self._handle(kind, payload, t_ns)
            for item in event if isinstance(event, list) else (event,):
                if item is not None:
                    sink(item)

    def _json(self, payload: bytes) -> dict:
        try:
            return ch.decode_json(payload)
        except ch.ChannelError as exc:
            raise ProtocolViolation(str(exc)) from None

    def _handle(self, kind: int, payload: bytes, t_ns: int):
        st = self.state
        if kind == ch.PUBLISH:
            ident, data = ch.split_id_bytes(payload)
            endpoint = st.publishers.get(ident)
            if endpoint is None or endpoint.closed:
                raise ProtocolViolation(f"PUBLISH on unknown or closed publisher handle {ident}")
            try:
                self._catalog.decode(endpoint.type, data)
            except RecordingError as exc:
                raise ProtocolViolation(f"message on {endpoint.topic} is not a valid {endpoint.type}: {exc}") from None
            endpoint.count += 1
            return Publication(endpoint, data)
        if kind == ch.OUTPUT:
            stream, text = ch.split_output(payload)
            return self._output(stream, text)
        obj = self._json(payload)
        if kind in (ch.ADVERTISE, ch.SUBSCRIBE):
            type_name = _field(obj, "type", str)
            if not self._catalog.known(type_name):
                raise ProtocolViolation(f"unknown message type {type_name[:80]!r}")
            if obj.get("md5sum") != self._catalog.md5sum(type_name):
                raise ProtocolViolation(f"md5sum for {type_name} does not match its definition")
            queue_size = obj.get("queue_size")
            endpoint = Endpoint(
                ident=_field(obj, "id", int), topic=_topic(_field(obj, "topic", str)), type=type_name,
                md5sum=_field(obj, "md5sum", str), queue_size=queue_size if isinstance(queue_size, int) else None,
                latch=bool(obj.get("latch", False)), registered_ns=t_ns)
            (st.publishers if kind == ch.ADVERTISE else st.subscribers)[endpoint.ident] = endpoint
            return endpoint if kind == ch.SUBSCRIBE else None
        if kind == ch.UNREGISTER:
            # Closed endpoints are kept (marked) so the run's diagnostics still count what they carried.
            ident = _field(obj, "id", int)
            for endpoint in (st.publishers.get(ident), st.subscribers.get(ident)):
                if endpoint is not None:
                    endpoint.closed = True
            return None
        if kind == ch.INIT:
            st.name = _field(obj, "name", str)[:256]
            st.init_ns = t_ns
            st.disable_signals = bool(obj.get("disable_signals", False))
            return None
        if kind == ch.LOG:
            level = _field(obj, "level", int)
            if level not in _LOG_LEVELS:
                raise ProtocolViolation(f"log level {level} is not a rosgraph_msgs/Log level")
            return LogLine(level, _field(obj, "msg", str), str(obj.get("name", st.name or "")),
                           str(obj.get("file", "")), str(obj.get("function", "")), int(obj.get("line") or 0))
        if kind == ch.EXCEPTION:
            where = str(obj.get("where", "uncaught"))[:40]
            info = {"type": str(obj.get("type", ""))[:200], "message": str(obj.get("message", ""))[:2000],
                    "frames": [f for f in obj.get("frames", [])[:50] if isinstance(f, dict)], "where": where}
            if where == "uncaught":
                st.exception = info
            elif len(st.caught) < 20:
                st.caught.append(info)
            return None
        raise ProtocolViolation(f"frame {ch.KIND_NAMES.get(kind, kind)} is not allowed here")

    def _output(self, stream: int, text: bytes) -> list[OutputLine] | None:
        st = self.state
        if st.output_truncated:
            return None
        st.output_bytes += len(text)
        if st.output_bytes > self._output_cap:
            st.output_truncated = True
            return [OutputLine(2, f"[rosgrade] output cut after {self._output_cap} bytes")]
        buf = self._partial[stream]
        buf += text
        *lines, rest = bytes(buf).split(b"\n")
        self._partial[stream] = bytearray(rest)
        out = [OutputLine(stream, line.decode("utf-8", "replace")) for line in lines]
        if stream == 2:
            st.stderr_tail.extend(line.text for line in out if line.text.strip())
        return out or None

    def flush_output(self) -> list[OutputLine]:
        """Lines left without a newline when the node ended."""
        lines = [OutputLine(s, bytes(b).decode("utf-8", "replace")) for s, b in self._partial.items() if b]
        self._partial = {1: bytearray(), 2: bytearray()}
        return lines

    # -- writing -----------------------------------------------------------------------------------------------
    def _send(self, data: bytes) -> None:
        try:
            ch.write_all(self._write_fd, data)
        except (BrokenPipeError, OSError):
            raise NodeExited() from None

    def resume(self, t_ns: int, clock_ns: int, deliveries: list[tuple[int, bytes]], shutdown: str | None) -> None:
        """Send one batch: the new time, messages for the node's subscribers, maybe Ctrl+C, then RESUME."""
        parts = [ch.encode_json(ch.ADVANCE, {"t_ns": t_ns, "clock_ns": clock_ns})]
        parts += [ch.encode_id_bytes(ch.DELIVER, ident, data) for ident, data in deliveries]
        if shutdown is not None:
            parts.append(ch.encode_json(ch.SHUTDOWN, {"reason": shutdown}))
        parts.append(ch.encode(ch.RESUME))
        self._send(b"".join(parts))
