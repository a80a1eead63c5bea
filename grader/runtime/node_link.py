"""The grader's side of one node: reads and validates its frames, tracks its topics, sends it time and messages.

Everything a node sends is untrusted data: frames are size-capped, JSON fields are type-checked, and message bytes
must decode exactly as the declared type before anything is recorded or reaches the robot.
"""
from __future__ import annotations

import os
import select
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field

from grader import timing
from grader.nodelib.common import rosgrade_channel as ch, rosgrade_qos
from grader.recording import MessageCatalog, RecordingError
from grader.runtime import frames


# A silence's watchdog is moved on by the node's run-queue wait for at most this many silence limits.
MAX_QUEUED_CREDIT = 2.0
# The robot's base as a receiver of a node's publications (node subscribers are (node index, handle) pairs).
ROBOT = "robot"


class ProtocolViolation(Exception):
    """The node sent something that is not a valid frame; it is stopped with this message."""


class NodeSilent(Exception):
    """The node ran longer than allowed without yielding to the grader."""


class NodeExited(Exception):
    """The node's end of the channel closed."""


class NodeOverLimit(Exception):
    """The node's processes together went over a limit while the grader waited for it; it is stopped."""


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
    qos: tuple[str, str] | None = None  # ROS 2: (reliability, durability) offered or requested; None: matches all
    count: int = 0
    closed: bool = False
    dropped_before_connect: int = 0
    latched: Latched | None = None  # a latched publisher's last message
    qos_told: set = field(default_factory=set)  # peers (node index, handle) it was told it cannot match (qos_match)
    ready_ns: int | None = None  # when a publisher connects, once the session has decided it (Session.ready_ns)
    last_data: bytes | None = None  # a publisher's last message (the node keeps it too: see inert batches)


@dataclass
class Latched:
    """The last message of a latched publisher: when it was published, whether it has gone out on its topic (it
    waits for the publisher to connect), and who has received it."""

    data: bytes
    t_ns: int
    sent: bool
    receivers: set = field(default_factory=set)


@dataclass
class Publication:
    endpoint: Endpoint
    data: bytes


@dataclass(frozen=True)
class ServiceCall:
    """A node's service call (``probe``: only asking whether the service is served, answered at once with a
    ServiceReply); its request bytes were checked against the srv type when the grader knows that type. The answer
    to a real call goes to the node's client handle ``ident`` for its call number ``seq`` in a later BATCH."""

    service: str
    type: str
    md5sum: str
    probe: bool
    request: bytes
    ident: int = 0
    seq: int = 0


@dataclass(frozen=True)
class ServiceOffer:
    """A node now serves ``endpoint.topic`` (the service's name) with srv type ``endpoint.type`` (SERVE)."""

    endpoint: Endpoint


@dataclass(frozen=True)
class ServiceAnswer:
    """A node's server answered request ``seq`` (RESPOND); the response bytes were checked as the srv's response."""

    endpoint: Endpoint
    seq: int
    status: str
    error: str
    response: bytes


@dataclass(frozen=True)
class ServiceReply:
    """The answer to a ServiceCall: a ``rosgrade_channel.SERVICE_*`` status, the server's error text, the response."""

    status: str
    error: str = ""
    response: bytes = b""


@dataclass(frozen=True)
class GraphQuery:
    """The node asks what of the run's graph it sees now (GRAPH); the sink returns the GRAPH_VIEW payload."""


@dataclass(frozen=True)
class ParamChange:
    """A node set (``value``) or deleted (``value`` None) the parameter ``name`` (absolute) on the run's server."""

    name: str
    value: object = None


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
    busy: bool = False  # its last WAIT was a busy loop's (a thread still runnable), not every thread blocked
    publishers: dict[int, Endpoint] = field(default_factory=dict)
    subscribers: dict[int, Endpoint] = field(default_factory=dict)
    services: dict[int, Endpoint] = field(default_factory=dict)  # what it serves (topic: the service's name)
    exception: dict | None = None  # the uncaught exception that ended the node, if any
    caught: list[dict] = field(default_factory=list)  # exceptions rospy printed and carried on from (callbacks, hooks)
    output_bytes: int = 0
    param_bytes: int = 0  # what its PARAM frames carried, against MAX_PARAM_BYTES
    output_truncated: bool = False
    stderr_tail: deque = field(default_factory=lambda: deque(maxlen=4))  # last lines, for start-up failures
    graph_version: int = 0  # counts its name and endpoint changes: what others see of it changed (runtime/graph.py)


# A node needs a handful of publishers and subscribers; past this many it is flooding the grader's memory and reports.
MAX_ENDPOINTS = 1000
# Bytes the grader holds for a node that is slow to read its batches; a node never legitimately needs more.
MAX_PENDING_BYTES = 32 * 1024 * 1024
# Bytes of parameter changes a node may send in one run (a node needs a few kilobytes): what other nodes are
# forwarded in one BATCH header then stays under the channel's frame cap even when every other node hits it.
MAX_PARAM_BYTES = 512 * 1024


class EndpointLimitExceeded(Exception):
    """The node registered more publishers and subscribers than MAX_ENDPOINTS; it is stopped."""


class ParamLimitExceeded(EndpointLimitExceeded):
    """The node's parameter changes carried more than MAX_PARAM_BYTES; it is stopped (as for too many endpoints)."""


def _topic(value: str, what: str = "topic") -> str:
    if not value.startswith("/") or any(c.isspace() for c in value):
        raise ProtocolViolation(f"invalid {what} name {value[:80]!r}")
    return value


def _qos(value: list[str] | None) -> tuple[str, str] | None:
    """A registration's QoS as the routing matches it, or a violation naming what is not a resolved policy pair."""
    if value is None:
        return None
    if len(value) != 2:
        raise ProtocolViolation(f"qos lists {len(value)} policies; it takes [reliability, durability]")
    try:
        return rosgrade_qos.check(value[0], value[1])
    except rosgrade_qos.QoSRuleError as exc:
        raise ProtocolViolation(str(exc)) from None


class NodeLink:
    """One node's channel, seen from the grader. Reads wait and writes never block, both under one wall-clock
    watchdog: a node that neither yields nor reads is stopped, the grader goes on."""

    def __init__(self, read_fd: int, write_fd: int, catalog: MessageCatalog, silent_wall_s: float,
                 output_cap: int, reserved_names: frozenset[str] = frozenset(),
                 over_limit: Callable[[], str | None] | None = None, check_every_s: float = 1.0,
                 queued_s: Callable[[], float] | None = None) -> None:
        self._reader = ch.FrameReader(read_fd, ch.NODE_KINDS, before_read=self._wait_readable)
        self._write_fd = write_fd
        os.set_blocking(write_fd, False)
        self._pending = bytearray()  # bytes for the node that its pipe has not taken yet
        self._catalog = catalog
        self._silent_wall_s = silent_wall_s
        self._output_cap = output_cap
        self._reserved = reserved_names
        self._deadline = 0.0
        self._over_limit = over_limit
        self._check_every_s = check_every_s
        self._queued_s = queued_s
        self._queued_seen: float | None = None  # the node's run-queue wait at the last check of this silence
        self._credited = 0.0  # run-queue wait credited to this silence so far
        self._partial = {1: bytearray(), 2: bytearray()}
        self.state = NodeState()

    # -- reading -----------------------------------------------------------------------------------------------
    def _wait_readable(self) -> None:
        """Wait until the node has something to read, writing what it still has to receive meanwhile."""
        started = time.perf_counter()
        try:
            self._select_until_readable()
        finally:
            timing.add("waiting for nodes", time.perf_counter() - started)

    def _select_until_readable(self) -> None:
        # A long wait may be a node (or its children) eating the machine: its totals are checked meanwhile, so that
        # it is stopped for that, and in time, rather than for its silence once the watchdog runs out.
        check_at = time.monotonic() + self._check_every_s
        while True:
            writing = [self._write_fd] if self._pending else []
            timeout = max(min(self._deadline, check_at) - time.monotonic(), 0)
            readable, writable, _ = select.select([self._reader.fd], writing, [], timeout)
            if writable:
                self._flush()
            if readable:
                return
            if writable:
                continue
            now = time.monotonic()
            if now >= check_at or now >= self._deadline:
                check_at = now + self._check_every_s
                self._check_in()

    def _check_in(self) -> None:
        """Stop the node if it is over a limit, or if it is past the watchdog's deadline once its run-queue wait is
        credited (checked while waiting to read, and between frames: a node that sends frames without end, GRAPH
        after GRAPH, never leaves a read waiting)."""
        why = self._over_limit() if self._over_limit is not None else None
        if why:
            raise NodeOverLimit(why)
        self._credit_queued_time()
        if time.monotonic() >= self._deadline:
            if self._pending:
                raise NodeSilent(f"did not read the grader's messages for {self._silent_wall_s:g} s of wall time")
            raise NodeSilent(f"did not yield to the grader for {self._silent_wall_s:g} s of wall time")

    def _credit_queued_time(self) -> None:
        """Move the watchdog on by the time the node spent runnable but waiting for a CPU since the last check: on a
        machine busy with other work that is not the node's silence (counted from the silence's first check on).
        At most MAX_QUEUED_CREDIT silence limits in all, so that a silence ends in bounded wall time on any load."""
        if self._queued_s is None:
            return
        queued = self._queued_s()
        if self._queued_seen is not None and queued > self._queued_seen:
            credit = min(queued - self._queued_seen, MAX_QUEUED_CREDIT * self._silent_wall_s - self._credited)
            self._deadline += credit
            self._credited += credit
        self._queued_seen = queued

    def _arm_watchdog(self) -> None:
        self._deadline = time.monotonic() + self._silent_wall_s
        self._queued_seen = None
        self._credited = 0.0

    def _read(self) -> tuple[int, bytes]:
        try:
            return self._reader.read()
        except ch.ChannelError as exc:
            if str(exc) == "channel closed":
                raise NodeExited() from None
            raise ProtocolViolation(str(exc)) from None

    def handshake(self, start: dict) -> dict:
        """Wait for HELLO, answer START; returns the HELLO payload."""
        self._arm_watchdog()
        kind, payload = self._read()
        if kind != ch.HELLO:
            raise ProtocolViolation(f"expected HELLO first, got {ch.KIND_NAMES.get(kind, kind)}")
        hello = self._parse(kind, payload)
        if hello.protocol != ch.PROTOCOL:
            raise ProtocolViolation(f"protocol {hello.protocol!r} is not {ch.PROTOCOL}")
        self._send(ch.encode_json(ch.START, start))
        return hello.model_dump()

    def run_until_wait(self, t_ns: int, sink: Callable[[object], ServiceReply | bytes | None],
                       inert: dict[int, bool] | None = None, at_moment: Callable[[int], int] | None = None,
                       on_act: Callable[[], None] | None = None) -> int | None:
        """Read frames until the node yields, passing each event at t_ns to sink; returns wake_ns or None.

        A probe ServiceCall is answered at once with the ServiceReply the sink returns for it (the node waits), a
        GraphQuery with the GRAPH_VIEW payload it returns.
        After a BATCH of moments (``inert``: its inert publishers, see rosgrade_channel.encode_batch) the node names
        each moment it sends something at (MOMENT) before that: ``at_moment`` gets its time and returns it, and what
        follows happens then. Its first frame that is not inert goes to ``on_act`` before it is handled, and ends
        the batch of moments there."""
        self._arm_watchdog()
        told = acted = False
        while True:
            kind, payload = self._read()
            if time.monotonic() >= self._deadline:
                self._check_in()
            if kind == ch.MOMENT:
                if inert is None or acted:
                    raise ProtocolViolation("MOMENT outside a batch of moments, or after the node acted in it")
                try:
                    t_ns, told = at_moment(ch.split_moment(payload)), True
                except ch.ChannelError as exc:
                    raise ProtocolViolation(str(exc)) from None
                continue
            if inert is not None and not told:
                raise ProtocolViolation(f"sent {ch.KIND_NAMES.get(kind, kind)} after a batch of moments without "
                                        "saying first which moment it was at (MOMENT)")
            if kind == ch.WAIT:
                plain, wake, busy = ch.plain_wait(payload)
                if not plain:
                    frame = self._parse(kind, payload)
                    wake, busy = frame.wake_ns, frame.busy
                self.state.busy = busy
                # A wake-up in the past would let a node stall the world forever: it costs at least one quantum.
                return max(wake, t_ns + ch.CALL_QUANTUM_NS) if wake is not None else None
            if inert is not None and not acted and not self._inert(kind, payload, inert):
                acted = True
                on_act()
            try:
                event = self._handle(kind, payload, t_ns)
            except ch.ChannelError as exc:
                raise ProtocolViolation(f"{ch.KIND_NAMES.get(kind, kind)} frame: {exc}") from None
            for item in event if isinstance(event, list) else (event,):
                if item is not None:
                    answer = sink(item)
                    if isinstance(item, ServiceCall) and item.probe:
                        self._reply(answer)
                    elif isinstance(item, GraphQuery):
                        self._send(ch.encode(ch.GRAPH_VIEW, answer))

    def _inert(self, kind: int, payload: bytes, inert: dict[int, bool]) -> bool:
        """Whether a frame leaves the world and the node's batches as they are (the node library's own rule)."""
        if kind in (ch.LOG, ch.OUTPUT):
            return True
        if kind != ch.PUBLISH or len(payload) < 4:
            return False
        ident, data = ch.split_id_bytes(payload)
        grant = inert.get(ident)
        endpoint = self.state.publishers.get(ident)
        return grant is True or (grant is False and endpoint is not None and endpoint.last_data == data)

    @staticmethod
    def _parse(kind: int, payload: bytes):
        """The one place a frame that breaks its schema becomes the node's protocol violation."""
        try:
            return frames.parse(kind, payload)
        except frames.FrameError as exc:
            raise ProtocolViolation(str(exc)) from None

    def _handle(self, kind: int, payload: bytes, t_ns: int):
        st = self.state
        if kind == ch.PUBLISH:
            ident, data = ch.split_id_bytes(payload)
            endpoint = st.publishers.get(ident)
            if endpoint is None or endpoint.closed:
                raise ProtocolViolation(f"PUBLISH on unknown or closed publisher handle {ident}")
            if data != endpoint.last_data:  # a repeated message was checked the first time
                try:
                    self._catalog.decode(endpoint.type, data)
                except RecordingError as exc:
                    raise ProtocolViolation(f"message on {endpoint.topic} is not a valid {endpoint.type}: {exc}") \
                        from None
            endpoint.count += 1
            endpoint.last_data = data
            return Publication(endpoint, data)
        if kind == ch.OUTPUT:
            stream, text = ch.split_output(payload)
            return self._output(stream, text)
        if kind == ch.CALL:
            header, request = ch.split_header_bytes(payload)
            return self._call(self._parse(kind, header), request)
        if kind == ch.GRAPH:
            if payload:
                raise ProtocolViolation(f"GRAPH carries {len(payload)} bytes; it asks with none")
            return GraphQuery()
        if kind == ch.RESPOND:
            header, response = ch.split_header_bytes(payload)
            return self._respond(self._parse(kind, header), response)
        frame = self._parse(kind, payload)
        if kind in (ch.ADVERTISE, ch.SUBSCRIBE):
            return self._register(kind, frame, t_ns)
        if kind == ch.SERVE:
            return self._serve(frame, t_ns)
        if kind == ch.UNREGISTER:
            # Closed endpoints are kept (marked) so the run's diagnostics still count what they carried.
            for endpoint in (st.publishers.get(frame.id), st.subscribers.get(frame.id), st.services.get(frame.id)):
                if endpoint is not None:
                    endpoint.closed = True
                    st.graph_version += 1
            return None
        if kind == ch.INIT:
            self._init(frame, t_ns)
            return None
        if kind == ch.PARAM:
            return self._param(frame, len(payload))
        if kind == ch.LOG:
            if frame.level not in self._catalog.log_levels:
                raise ProtocolViolation(f"log level {frame.level} is not one of "
                                        f"{', '.join(map(str, sorted(self._catalog.log_levels)))}")
            return LogLine(frame.level, frame.msg, frame.name or st.name or "", frame.file, frame.function,
                           frame.line)
        if kind == ch.EXCEPTION:
            info = frame.model_dump()
            if frame.where == "uncaught":
                st.exception = info
            elif len(st.caught) < 20:
                st.caught.append(info)
            return None
        raise ProtocolViolation(f"frame {ch.KIND_NAMES.get(kind, kind)} is not allowed here")

    def _register(self, kind: int, frame: frames.Register, t_ns: int) -> Endpoint | None:
        st = self.state
        if not self._catalog.known(frame.type):
            raise ProtocolViolation(f"unknown message type {frame.type[:80]!r}")
        if frame.md5sum != self._catalog.md5sum(frame.type):
            raise ProtocolViolation(f"md5sum for {frame.type} does not match its definition")
        table = st.publishers if kind == ch.ADVERTISE else st.subscribers
        if frame.id not in table and len(st.publishers) + len(st.subscribers) >= MAX_ENDPOINTS:
            raise EndpointLimitExceeded(f"registered more than {MAX_ENDPOINTS} publishers and subscribers; "
                                        "it was stopped")
        endpoint = Endpoint(ident=frame.id, topic=_topic(frame.topic), type=self._catalog.canonical(frame.type),
                            md5sum=frame.md5sum,
                            queue_size=frame.queue_size, latch=frame.latch, registered_ns=t_ns,
                            qos=_qos(frame.qos))
        table[endpoint.ident] = endpoint
        st.graph_version += 1
        return endpoint if kind == ch.SUBSCRIBE else None

    def _call(self, frame: frames.Call, request: bytes) -> ServiceCall:
        """A service call, with its request checked as PUBLISH checks a message (when the srv type is known)."""
        service = _topic(frame.service, "service")
        known = self._catalog.known_service(frame.type)
        if known and frame.md5sum != self._catalog.service_md5sum(frame.type):
            raise ProtocolViolation(f"md5sum for service type {frame.type} does not match its definition")
        if frame.probe:
            if request:
                raise ProtocolViolation(f"CALL probe of {service} carries {len(request)} request bytes")
        elif known:
            try:
                self._catalog.decode(self._catalog.service_part(frame.type, "Request"), request)
            except RecordingError as exc:
                raise ProtocolViolation(f"request to {service} is not a valid {frame.type} request: {exc}") from None
        return ServiceCall(service, frame.type, frame.md5sum, frame.probe, request, frame.id, frame.seq)

    def _serve(self, frame: frames.Serve, t_ns: int) -> ServiceOffer:
        """A service the node offers: a srv type the grader knows must carry its own md5sum (or type hash)."""
        st = self.state
        if self._catalog.known_service(frame.type) and frame.md5sum != self._catalog.service_md5sum(frame.type):
            raise ProtocolViolation(f"md5sum for service type {frame.type} does not match its definition")
        if frame.id in st.publishers or frame.id in st.subscribers or frame.id in st.services:
            raise ProtocolViolation(f"SERVE with handle {frame.id}, which the node already uses")
        if len(st.publishers) + len(st.subscribers) + len(st.services) >= MAX_ENDPOINTS:
            raise EndpointLimitExceeded(f"registered more than {MAX_ENDPOINTS} publishers, subscribers and "
                                        "services; it was stopped")
        endpoint = Endpoint(ident=frame.id, topic=_topic(frame.service, "service"), type=frame.type,
                            md5sum=frame.md5sum, queue_size=None, latch=False, registered_ns=t_ns)
        st.services[frame.id] = endpoint
        st.graph_version += 1
        return ServiceOffer(endpoint)

    def _respond(self, frame: frames.Respond, response: bytes) -> ServiceAnswer:
        """A server's answer, its response checked as PUBLISH checks a message (when the srv type is known)."""
        endpoint = self.state.services.get(frame.id)
        if endpoint is None or endpoint.closed:
            raise ProtocolViolation(f"RESPOND on unknown or withdrawn service handle {frame.id}")
        if frame.status != ch.SERVICE_OK and response:
            raise ProtocolViolation(f"RESPOND {frame.status} on {endpoint.topic} carries {len(response)} bytes")
        if frame.status == ch.SERVICE_OK and self._catalog.known_service(endpoint.type):
            try:
                self._catalog.decode(self._catalog.service_part(endpoint.type, "Response"), response)
            except RecordingError as exc:
                raise ProtocolViolation(f"response of {endpoint.topic} is not a valid {endpoint.type} response: "
                                        f"{exc}") from None
        endpoint.count += 1
        return ServiceAnswer(endpoint, frame.seq, frame.status, frame.error, response)

    def _param(self, frame: frames.Param, size: int) -> ParamChange:
        """A parameter change: an absolute name (the root only takes a namespace), within the node's byte budget."""
        st = self.state
        name = _topic(frame.name, "parameter")
        if name.strip("/") == "" and frame.op == ch.PARAM_DELETE:
            raise ProtocolViolation("PARAM delete of the root of the parameter tree, which cannot be deleted")
        if name.strip("/") == "" and not isinstance(frame.value, dict):
            raise ProtocolViolation("PARAM set of the root of the parameter tree to a value that is not a dict")
        st.param_bytes += size
        if st.param_bytes > MAX_PARAM_BYTES:
            raise ParamLimitExceeded(f"changed parameters by more than {MAX_PARAM_BYTES} bytes; it was stopped")
        return ParamChange(name, frame.value if frame.op == ch.PARAM_SET else None)

    def _init(self, frame: frames.Init, t_ns: int) -> None:
        """A node's name is fixed by its first init_node, and never one of the grader's own."""
        st = self.state
        if st.name is not None:
            raise ProtocolViolation(f"INIT again as {frame.name[:80]!r} after init_node named it {st.name}: "
                                    "a node's name is fixed by its first init_node")
        if frame.name in self._reserved or frame.name.startswith("/rosgrade"):
            raise ProtocolViolation(
                f"init_node named it {frame.name}, a name reserved for the grader's own nodes "
                f"({', '.join(sorted(self._reserved))}, /rosgrade...); on a real ROS system a second node with that "
                "name shuts the first one down. Choose another name")
        st.name, st.init_ns, st.disable_signals = frame.name, t_ns, frame.disable_signals
        st.graph_version += 1

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
        """Queue bytes for the node and write what its pipe takes now; the rest goes out while waiting to read."""
        if len(self._pending) + len(data) > MAX_PENDING_BYTES:
            raise NodeSilent(f"did not read the grader's messages ({len(self._pending)} bytes waiting)")
        self._pending += data
        self._flush()

    def _flush(self) -> None:
        try:
            written = os.write(self._write_fd, self._pending)
        except BlockingIOError:
            return
        except OSError:
            raise NodeExited() from None
        del self._pending[:written]

    def _reply(self, reply: ServiceReply) -> None:
        """Send the REPLY to the node's probe CALL."""
        if not isinstance(reply, ServiceReply) or reply.status not in ch.SERVICE_STATUSES:
            raise TypeError(f"a service call needs a ServiceReply, the session gave {reply!r}")
        self._send(ch.encode_header_bytes(ch.REPLY, {"status": reply.status, "error": reply.error}, reply.response))

    def resume(self, t_ns: int, clock_ns: int, deliveries: list[tuple[int, bytes]], shutdown: str | None,
               connections: dict[int, int] | None = None, params: list[tuple[str, object]] | None = None,
               later: list[tuple[int, int, list[tuple[int, bytes]]]] = (), until_ns: int | None = None,
               inert: dict[int, bool] | None = None, qos_events: list[tuple[int, str]] = ()) -> None:
        """Send one BATCH frame: the new time (with changed connection counts per topic handle, and the parameter
        changes others made, in order), messages for the node's subscribers and maybe Ctrl+C; the node runs until
        its next WAIT. ``later``: (t_ns, clock_ns, deliveries) of later moments it may run on its own, with its own
        wake-ups, up to ``until_ns``; ``inert``: its publishers that do not end that (see encode_batch);
        ``qos_events``: (handle, policy) per peer endpoint just discovered whose QoS is incompatible (qos_match)."""
        header: dict = {"t_ns": t_ns, "clock_ns": clock_ns}
        if until_ns is not None:
            header["moments"] = [[t, clock, len(items)] for t, clock, items in later]
            header["until"] = until_ns
            header["inert"] = {str(ident): "any" if grant else "same" for ident, grant in (inert or {}).items()}
            deliveries = deliveries + [item for _, _, items in later for item in items]
        if connections:
            header["connections"] = {str(ident): count for ident, count in connections.items()}
        if params:
            header["params"] = [[name, value] for name, value in params]
        if shutdown is not None:
            header["shutdown"] = shutdown
        if qos_events:
            header["qos"] = [[ident, policy] for ident, policy in qos_events]
        self._send(ch.encode_batch(header, deliveries))
