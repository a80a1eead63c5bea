"""The node's end of the grader channel: ordered, write-through frame sending and batch reading."""
from __future__ import annotations

import os
import threading

import rosgrade_channel as ch

# OUTPUT payloads are split so that no frame comes near the grader's size cap.
_OUTPUT_CHUNK = 64 * 1024


# Plain slotted classes, not dataclasses: every node imports this module first thing, and dataclasses (with the
# inspect and ast modules it needs) was about a fifth of the node library's import time.
class Moment:
    """A later time of a batch: its clock and the messages delivered then."""

    __slots__ = ("t_ns", "clock_ns", "deliveries")

    def __init__(self, t_ns: int, clock_ns: int, deliveries: list[tuple[int, bytes]]) -> None:
        self.t_ns, self.clock_ns, self.deliveries = t_ns, clock_ns, deliveries


class Batch:
    """What the grader sent in answer to a WAIT (one BATCH frame)."""

    __slots__ = ("t_ns", "clock_ns", "deliveries", "moments", "until_ns", "inert", "shutdown", "connections",
                 "params", "qos_events")

    def __init__(self, t_ns: int, clock_ns: int, deliveries: list[tuple[int, bytes]], moments: list[Moment],
                 until_ns: int | None, inert: dict[int, bool], shutdown: str | None, connections: dict[int, int],
                 params: list[tuple[str, object]], qos_events: list[tuple[int, str]] = ()) -> None:
        self.t_ns, self.clock_ns, self.deliveries = t_ns, clock_ns, deliveries
        # Later times, in order, that the node runs on its own while what it does is invisible (see Scheduler), and
        # how far the world ran ahead (None: a plain batch): the node's own wake-ups up to then are moments too.
        self.moments = moments
        self.until_ns = until_ns
        # Publisher handles whose messages change nothing before until_ns: True, any message; False, only the
        # publisher's last message again (a robot's command repeated).
        self.inert = inert
        self.shutdown = shutdown
        self.connections = connections  # changed connection counts per topic handle
        # Parameter changes other nodes (or the world) made since the last batch, in order: [name, value (None:
        # deleted)].
        self.params = params
        # (handle, policy): a peer endpoint discovered whose QoS the handle's endpoint cannot match (ROS 2).
        self.qos_events = qos_events


class Link:
    """Frames to and from the grader. Every frame is written at once (nothing is lost if the node is killed)."""

    def __init__(self, read_fd: int, write_fd: int) -> None:
        self._reader = ch.FrameReader(read_fd, ch.GRADER_KINDS)
        self._wfd = write_fd
        self._lock = threading.Lock()
        # The time of the moment of a batch of moments the node is at, until the grader has been told (a MOMENT
        # frame goes out in the same write as the next frame, or alone at exit).
        self.pending_moment: int | None = None
        # Set by any frame that could change the world or the node's next batches: it ends a batch of moments.
        self.acted = False
        self._inert: dict[int, bool] = {}
        self._last: dict[int, bytes] = {}  # each publisher's last message, as the grader also keeps it

    def begin_moments(self, t_ns: int, inert: dict[int, bool]) -> None:
        """A batch of moments starts at ``t_ns``: nothing has been done yet; ``inert`` as in Batch."""
        self.pending_moment, self.acted, self._inert = t_ns, False, inert

    def send(self, frame: bytes, inert: bool = False) -> None:
        """Write one frame; ``inert``: it cannot change the world (a log line, printed text, an inert message)."""
        try:
            with self._lock:
                if self.pending_moment is not None:
                    frame = ch.encode_moment(self.pending_moment) + frame
                    self.pending_moment = None
                ch.write_all(self._wfd, frame)
                if not inert:
                    self.acted = True
        except OSError as exc:
            # The grader is gone: there is nobody left to run for.
            _fail(exc)

    def send_pending_moment(self) -> None:
        """Tell the grader the moment the node is at, if it has not been told (the node is ending there)."""
        try:
            with self._lock:
                if self.pending_moment is not None:
                    ch.write_all(self._wfd, ch.encode_moment(self.pending_moment))
                    self.pending_moment = None
        except OSError:
            pass  # the grader is gone: nobody is left to tell

    def send_json(self, kind: int, obj: dict) -> None:
        self.send(ch.encode_json(kind, obj), inert=kind == ch.LOG)

    def send_output(self, stream: int, data: bytes) -> None:
        for start in range(0, len(data), _OUTPUT_CHUNK):
            self.send(ch.encode_output(stream, data[start:start + _OUTPUT_CHUNK]), inert=True)

    def send_message(self, kind: int, ident: int, data: bytes) -> None:
        """A PUBLISH: inert when the grader said so for its publisher (for "same", when it repeats the last one)."""
        grant = self._inert.get(ident)
        inert = grant is True or (grant is False and self._last.get(ident) == data)
        self._last[ident] = data
        self.send(ch.encode_id_bytes(kind, ident, data), inert)

    def call(self, header: dict, request: bytes) -> tuple[dict, bytes]:
        """Send a probe CALL and read its REPLY: (the reply's header, the response bytes). A real call's answer comes
        in a later BATCH instead.

        The grader answers a probe at once, before anything else, so only the thread holding the scheduler's token
        may probe (no other thread reads the channel meanwhile)."""
        self.send(ch.encode_header_bytes(ch.CALL, header, request))
        try:
            head, response = ch.split_header_bytes(self._read(ch.REPLY))
            return ch.decode_json(head), response
        except (ch.ChannelError, OSError) as exc:
            _fail(exc)

    def graph(self) -> dict:
        """Send GRAPH and read its GRAPH_VIEW: the other nodes of the run the node has discovered, with their
        publishers, subscribers and services (the grader answers at once, as it answers a probe CALL)."""
        self.send(ch.encode(ch.GRAPH))
        try:
            return ch.decode_json(self._read(ch.GRAPH_VIEW), limit=ch.MAX_FRAME_BYTES)
        except (ch.ChannelError, OSError) as exc:
            _fail(exc)

    def read_json(self, kind: int) -> dict:
        """Read one frame that must be of ``kind`` and carry JSON."""
        try:
            return self._read_json(kind)
        except (ch.ChannelError, OSError) as exc:
            _fail(exc)

    def read_batch(self) -> Batch:
        """Read one BATCH: the new time, changed connection counts and parameters, deliveries and maybe a shutdown
        request."""
        try:
            header, deliveries = ch.decode_batch(self._read(ch.BATCH))
            shutdown = header.get("shutdown")
            moments = _moments(header.get("moments") or [], deliveries)
            t_ns = _int(header, "t_ns")
            until = None if header.get("until") is None else _int(header, "until")
            if (until is None and moments) or (until is not None and until < max([t_ns, *(m.t_ns for m in moments)])):
                raise ch.ChannelError("BATCH until must come with moments, at or after the batch's last time")
            return Batch(t_ns=t_ns, clock_ns=_int(header, "clock_ns"), deliveries=deliveries,
                         moments=moments, until_ns=until,
                         inert=_grants(header.get("inert") or {}), shutdown=None if shutdown is None else str(shutdown),
                         connections=_counts(header.get("connections") or {}),
                         params=_changes(header.get("params") or []), qos_events=_qos_events(header.get("qos") or []))
        except (ch.ChannelError, OSError) as exc:
            _fail(exc)

    def _read(self, kind: int) -> bytes:
        got, payload = self._reader.read()
        if got != kind:
            raise ch.ChannelError(f"expected {ch.KIND_NAMES[kind]}, got {ch.KIND_NAMES.get(got, got)}")
        return payload

    def _read_json(self, kind: int) -> dict:
        return ch.decode_json(self._read(kind))


def _fail(exc: BaseException) -> NoReturn:  # a string annotation: typing is not imported for it
    """The grader closed the channel or broke the protocol: say why on the real stderr and end the process."""
    try:
        os.write(2, f"rosgrade node: channel error: {exc}\n".encode())
    finally:
        os._exit(1)


def _counts(obj) -> dict[int, int]:
    if not isinstance(obj, dict):
        raise ch.ChannelError("BATCH connections must be an object")
    try:
        return {int(ident): _int(obj, ident) for ident in obj}
    except ValueError:
        raise ch.ChannelError("BATCH connections must map topic handles to counts") from None


def _qos_events(obj) -> list[tuple[int, str]]:
    if not isinstance(obj, list) or not all(isinstance(e, list) and len(e) == 2 and isinstance(e[0], int)
                                            and e[1] in ("RELIABILITY", "DURABILITY") for e in obj):
        raise ch.ChannelError("BATCH qos must list [topic handle, RELIABILITY or DURABILITY] pairs")
    return [(ident, policy) for ident, policy in obj]


def _moments(obj, deliveries: list[tuple[int, bytes]]) -> list[Moment]:
    """The later moments of a BATCH header; their deliveries are taken off the end of ``deliveries``."""
    if not isinstance(obj, list) or not all(isinstance(m, list) and len(m) == 3 for m in obj):
        raise ch.ChannelError("BATCH moments must be a list of [t_ns, clock_ns, deliveries] triples")
    counts = [_count(m[2], "deliveries") for m in obj]
    if sum(counts) > len(deliveries):
        raise ch.ChannelError("BATCH moments claim more deliveries than the batch carries")
    start = len(deliveries) - sum(counts)
    moments = []
    for (t_ns, clock_ns, _), count in zip(obj, counts):
        moments.append(Moment(_count(t_ns, "t_ns"), _count(clock_ns, "clock_ns"),
                              deliveries[start:start + count]))
        start += count
    del deliveries[len(deliveries) - sum(counts):]
    return moments


def _grants(obj) -> dict[int, bool]:
    if not isinstance(obj, dict) or not all(grant in ("any", "same") for grant in obj.values()):
        raise ch.ChannelError('BATCH inert must map publisher handles to "any" or "same"')
    try:
        return {int(ident): grant == "any" for ident, grant in obj.items()}
    except ValueError:
        raise ch.ChannelError("BATCH inert must map publisher handles to grants") from None


def _changes(obj) -> list[tuple[str, object]]:
    if not isinstance(obj, list) or not all(isinstance(c, list) and len(c) == 2 and isinstance(c[0], str)
                                            for c in obj):
        raise ch.ChannelError("BATCH params must be a list of [name, value] pairs")
    return [(name, value) for name, value in obj]


def _int(obj: dict, key: str) -> int:
    return _count(obj.get(key), key)


def _count(value: object, key: str) -> int:
    """``value`` when it is a non-negative integer (the field ``key`` of a header); a channel error otherwise."""
    if type(value) is not int or value < 0:  # type(): bool is an int to isinstance
        raise ch.ChannelError(f"field {key!r} must be a non-negative integer, got {value!r}")
    return value
