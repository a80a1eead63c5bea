"""Frame codec for the data-only channel between the grader and a node process (stdlib only: it runs on both sides).

A frame is ``u32 length (little-endian) | u8 kind | payload``; ``length`` counts the kind byte and the payload.
Payloads are JSON objects or raw ROS 1 message bytes, never anything that is executed or unpickled.
"""
from __future__ import annotations

import json
import os
import re
import struct

PROTOCOL = 10  # 10: a ROS 2 ADVERTISE/SUBSCRIBE carries "qos": [reliability, durability] (rosgrade_qos)

CLOCK_PERIOD_NS = 10_000_000
CALL_QUANTUM_NS = 1_000_000

MAX_FRAME_BYTES = 8 * 1024 * 1024
MAX_JSON_BYTES = 256 * 1024
# Field bounds of the JSON frames: the node library cuts to them, the grader's schemas refuse anything longer.
MAX_NAME_CHARS = 256  # node, topic and type names
MAX_LABEL_CHARS = 200  # exception type and function names
MAX_PATH_CHARS = 4096
MAX_MESSAGE_CHARS = 4000  # exception messages and traceback source lines
MAX_TRACEBACK_FRAMES = 50

# node -> grader
HELLO = 1
INIT = 2
ADVERTISE = 3
SUBSCRIBE = 4
UNREGISTER = 5
PUBLISH = 6
LOG = 7
OUTPUT = 8
EXCEPTION = 9
WAIT = 10
CALL = 11
PARAM = 12
MOMENT = 13
SERVE = 14
RESPOND = 15
GRAPH = 16  # what of the run's graph the node sees now: answered at once with a GRAPH_VIEW
# grader -> node
START = 32
BATCH = 33
REPLY = 34
GRAPH_VIEW = 35  # JSON {"nodes": [{"name", "kind", "pub", "sub", "srv"}, ...]}: the other nodes it has discovered

# PARAM operations: a node set or deleted a parameter of the run's one parameter server.
PARAM_SET = "set"
PARAM_DELETE = "delete"

# REPLY statuses: what became of a CALL (each client library words its own exception from them).
SERVICE_OK = "ok"  # the response follows
SERVICE_UNAVAILABLE = "unavailable"  # nothing serves that name
SERVICE_REFUSED = "refused"  # the server refused the connection (another srv type); error: the server's reason
SERVICE_FAILED = "failed"  # the server's handler failed; error: the text the server sent ('' from a roscpp false)
SERVICE_LOST = "lost"  # the server's node ended before it answered (rospy: the connection closed)
SERVICE_STATUSES = frozenset({SERVICE_OK, SERVICE_UNAVAILABLE, SERVICE_REFUSED, SERVICE_FAILED, SERVICE_LOST})
# A BATCH delivery on a server's handle with this status is a request for it to answer (RESPOND).
SERVICE_REQUEST = "request"

KIND_NAMES = {
    HELLO: "HELLO", INIT: "INIT", ADVERTISE: "ADVERTISE", SUBSCRIBE: "SUBSCRIBE", UNREGISTER: "UNREGISTER",
    PUBLISH: "PUBLISH", LOG: "LOG", OUTPUT: "OUTPUT", EXCEPTION: "EXCEPTION", WAIT: "WAIT", CALL: "CALL",
    PARAM: "PARAM", MOMENT: "MOMENT", SERVE: "SERVE", RESPOND: "RESPOND", GRAPH: "GRAPH",
    START: "START", BATCH: "BATCH", REPLY: "REPLY", GRAPH_VIEW: "GRAPH_VIEW",
}
NODE_KINDS = frozenset({HELLO, INIT, ADVERTISE, SUBSCRIBE, UNREGISTER, PUBLISH, LOG, OUTPUT, EXCEPTION, WAIT, CALL,
                        PARAM, MOMENT, SERVE, RESPOND, GRAPH})
GRADER_KINDS = frozenset({START, BATCH, REPLY, GRAPH_VIEW})
JSON_KINDS = frozenset({HELLO, INIT, ADVERTISE, SUBSCRIBE, UNREGISTER, LOG, EXCEPTION, WAIT, START, PARAM, SERVE})

_HEADER = struct.Struct("<IB")
_ID = struct.Struct("<I")
_ID_LEN = struct.Struct("<II")
_STREAM = struct.Struct("<B")
_TIME = struct.Struct("<Q")
# Every lockstep step sends one BATCH and one WAIT, and almost all of them carry nothing but times: those two
# headers are written and read without the json module (the same bytes json.dumps writes, so the contract is still
# JSON); anything else goes through json.
_PLAIN_BATCH = re.compile(rb'\{"t_ns":(0|[1-9][0-9]{0,18}),"clock_ns":(0|[1-9][0-9]{0,18})\}')
_PLAIN_WAIT = re.compile(rb'\{"wake_ns":(?:null|(0|[1-9][0-9]{0,18}))(,"busy":true)?\}')


class ChannelError(Exception):
    """The other side broke the protocol or closed the channel."""


def encode(kind: int, payload: bytes = b"") -> bytes:
    """One frame as bytes."""
    return _HEADER.pack(len(payload) + 1, kind) + payload


def encode_json(kind: int, obj: dict) -> bytes:
    return encode(kind, json.dumps(obj, separators=(",", ":")).encode())


def encode_id_bytes(kind: int, ident: int, data: bytes) -> bytes:
    """A PUBLISH frame: a topic handle and a serialized message."""
    return encode(kind, _ID.pack(ident) + data)


def encode_batch(header: dict, deliveries: list[tuple[int, bytes]]) -> bytes:
    """A BATCH frame: everything the node gets at one world time, so one write and one read per wake-up.

    Payload: ``u32 header length | header JSON | (u32 topic handle | u32 length | message bytes)*``. A header's
    ``moments`` (``[[t_ns, clock_ns, deliveries], ...]``) are later times the node may run on its own: the last
    that many deliveries belong to them, in order, and the rest to the batch's own time. ``until`` is how far the
    world has run ahead: the node may also run its own wake-ups up to it. ``inert`` names the publishers whose
    messages cannot change the world before then (``"any"``), or only when they repeat the publisher's last
    message (``"same"``): publishing on them, logging and printing do not end the node's run on its own.

    A delivery may be ``(handle, bytes, (callerid, latched))``: a node's publication, sent with the publishing
    node's name and whether its publisher latches (rospy keeps one connection per publisher); the header's
    ``from`` lists them as ``[delivery index, callerid, latched]``. The others are the world's.

    A delivery on a service handle is ``(handle, bytes, (seq, status, error))``: a request for a server to answer
    (status SERVICE_REQUEST, ``seq`` the grader's number for it) or the answer to a client's call ``seq`` (bytes
    only when ``ok``); the header's ``svc`` lists them as ``[delivery index, seq, status, error]``.
    """
    sources = [[i, *item[2]] for i, item in enumerate(deliveries) if len(item) > 2 and len(item[2]) == 2]
    if sources:
        header = {**header, "from": sources}
    services = [[i, *item[2]] for i, item in enumerate(deliveries) if len(item) > 2 and len(item[2]) == 3]
    if services:
        header = {**header, "svc": services}
    t_ns, clock_ns = header.get("t_ns"), header.get("clock_ns")
    if len(header) == 2 and type(t_ns) is int and type(clock_ns) is int and t_ns >= 0 and clock_ns >= 0:
        head = b'{"t_ns":%d,"clock_ns":%d}' % (t_ns, clock_ns)
    else:
        head = json.dumps(header, separators=(",", ":")).encode()
    parts = [_ID.pack(len(head)), head]
    for ident, data, *_ in deliveries:
        parts += (_ID_LEN.pack(ident, len(data)), data)
    return encode(BATCH, b"".join(parts))


def encode_moment(t_ns: int) -> bytes:
    """A MOMENT frame: the node is at world time ``t_ns`` of a batch of moments (the batch's own time, a later
    moment's or a wake-up of its own before the batch's horizon); everything it sends next happens then."""
    return encode(MOMENT, _TIME.pack(t_ns))


def split_moment(payload: bytes) -> int:
    if len(payload) != 8:
        raise ChannelError("MOMENT frame payload is not one 8-byte world time")
    return _TIME.unpack(payload)[0]


def decode_batch(payload: bytes) -> tuple[dict, list[tuple]]:
    """The header object and the (topic handle, message bytes) deliveries of a BATCH payload; a node's publication
    comes as (topic handle, message bytes, (callerid, latched)) (see encode_batch)."""
    if len(payload) < 4:
        raise ChannelError("BATCH frame shorter than its header length")
    end = 4 + _ID.unpack_from(payload)[0]
    if end > len(payload):
        raise ChannelError("BATCH header runs past the end of the frame")
    plain = _PLAIN_BATCH.fullmatch(payload, 4, end)
    if plain is not None:
        header: dict = {"t_ns": int(plain.group(1)), "clock_ns": int(plain.group(2))}
    else:
        # The header may carry other nodes' parameter changes: bounded by the frame, not by MAX_JSON_BYTES.
        header = decode_json(payload[4:end], limit=MAX_FRAME_BYTES)
    deliveries = []
    while end < len(payload):
        if end + 8 > len(payload):
            raise ChannelError("BATCH delivery cut short")
        ident, size = _ID_LEN.unpack_from(payload, end)
        end += 8 + size
        if end > len(payload):
            raise ChannelError("BATCH delivery runs past the end of the frame")
        deliveries.append((ident, payload[end - size:end]))
    for source in header.pop("from", None) or ():
        if not (isinstance(source, list) and len(source) == 3 and type(source[0]) is int
                and 0 <= source[0] < len(deliveries) and isinstance(source[1], str) and type(source[2]) is bool):
            raise ChannelError("BATCH from must list [delivery index, callerid, latched] triples")
        index, callerid, latched = source
        deliveries[index] = (*deliveries[index][:2], (callerid, latched))
    for item in header.pop("svc", None) or ():
        if not (isinstance(item, list) and len(item) == 4 and type(item[0]) is int and 0 <= item[0] < len(deliveries)
                and type(item[1]) is int and item[1] >= 0 and isinstance(item[2], str) and isinstance(item[3], str)):
            raise ChannelError("BATCH svc must list [delivery index, seq, status, error] quadruples")
        index, seq, status, error = item
        deliveries[index] = (*deliveries[index][:2], (seq, status, error))
    return header, deliveries


def encode_wait(wake_ns: int | None, busy: bool = False) -> bytes:
    """A WAIT frame: ``{"wake_ns": n}`` (null: nothing to wake for but messages), with ``"busy": true`` when a thread
    of the node is still runnable and only gives up the sim time its calls charged (a busy loop)."""
    wake = b'{"wake_ns":null' if wake_ns is None else b'{"wake_ns":%d' % wake_ns
    return encode(WAIT, wake + (b',"busy":true}' if busy else b'}'))


def plain_wait(payload: bytes) -> tuple[bool, int | None, bool]:
    """(True, wake_ns, busy) when a WAIT payload is exactly what encode_wait writes; (False, None, False) for anything
    else, which the grader then checks against the WAIT schema (and words the violation)."""
    match = _PLAIN_WAIT.fullmatch(payload)
    if match is None:
        return False, None, False
    return True, None if match.group(1) is None else int(match.group(1)), match.group(2) is not None


def encode_header_bytes(kind: int, header: dict, data: bytes) -> bytes:
    """A CALL, RESPOND or REPLY frame: ``u32 header length | header JSON | message bytes`` (a request or a response)."""
    head = json.dumps(header, separators=(",", ":")).encode()
    return encode(kind, _ID.pack(len(head)) + head + data)


def split_header_bytes(payload: bytes) -> tuple[bytes, bytes]:
    """The JSON header (still bytes: each side validates it its own way) and the message bytes of a CALL, RESPOND or
    REPLY."""
    if len(payload) < 4:
        raise ChannelError("frame shorter than its header length")
    end = 4 + _ID.unpack_from(payload)[0]
    if end > len(payload):
        raise ChannelError("header runs past the end of the frame")
    return payload[4:end], payload[end:]


def encode_output(stream: int, text: bytes) -> bytes:
    return encode(OUTPUT, _STREAM.pack(stream) + text)


def split_id_bytes(payload: bytes) -> tuple[int, bytes]:
    if len(payload) < 4:
        raise ChannelError("message frame shorter than its 4-byte topic handle")
    return _ID.unpack_from(payload)[0], payload[4:]


def split_output(payload: bytes) -> tuple[int, bytes]:
    if not payload or payload[0] not in (1, 2):
        raise ChannelError("output frame without a valid stream number")
    return payload[0], payload[1:]


def decode_json(payload: bytes, limit: int = MAX_JSON_BYTES) -> dict:
    """Parse a JSON payload strictly: size-capped, must be an object."""
    if len(payload) > limit:
        raise ChannelError(f"JSON frame of {len(payload)} bytes exceeds {limit}")
    try:
        obj = json.loads(payload.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError) as exc:
        raise ChannelError(f"frame is not valid JSON: {exc}") from None
    if not isinstance(obj, dict):
        raise ChannelError("JSON frame is not an object")
    return obj


class FrameReader:
    """Reads whole frames from a file descriptor, with a size cap; raises ChannelError on EOF or garbage."""

    def __init__(self, fd: int, allowed: frozenset[int], max_frame: int = MAX_FRAME_BYTES,
                 before_read=None) -> None:
        self.fd = fd
        self.allowed = allowed
        self.max_frame = max_frame
        # The grader passes a callable that waits (with a wall-clock deadline) until the fd is readable,
        # so a node that stops mid-frame cannot block it forever.
        self.before_read = before_read
        self._buf = bytearray()

    def _fill(self, need: int) -> None:
        while len(self._buf) < need:
            if self.before_read is not None:
                self.before_read()
            chunk = os.read(self.fd, max(65536, need - len(self._buf)))
            if not chunk:
                raise ChannelError("channel closed")
            self._buf += chunk

    def buffered(self) -> bool:
        """True when a complete frame header is already buffered (no read needed to start the next frame)."""
        return len(self._buf) >= _HEADER.size

    def read(self) -> tuple[int, bytes]:
        self._fill(_HEADER.size)
        length, kind = _HEADER.unpack_from(self._buf)
        if length < 1 or length > self.max_frame:
            raise ChannelError(f"frame length {length} outside 1..{self.max_frame}")
        if kind not in self.allowed:
            raise ChannelError(f"unexpected frame kind {kind}")
        self._fill(4 + length)
        payload = bytes(self._buf[_HEADER.size:4 + length])
        del self._buf[:4 + length]
        return kind, payload


def write_all(fd: int, data: bytes) -> None:
    """Write every byte (pipes may accept a partial write)."""
    view = memoryview(data)
    while view:
        n = os.write(fd, view)
        view = view[n:]
