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

    __slots__ = ("t_ns", "clock_ns", "deliveries", "moments", "shutdown", "connections", "params")

    def __init__(self, t_ns: int, clock_ns: int, deliveries: list[tuple[int, bytes]], moments: list[Moment],
                 shutdown: str | None, connections: dict[int, int], params: list[tuple[str, object]]) -> None:
        self.t_ns, self.clock_ns, self.deliveries = t_ns, clock_ns, deliveries
        # Later times, in order, that the node runs on its own while what it does is invisible (see Scheduler).
        self.moments = moments
        self.shutdown = shutdown
        self.connections = connections  # changed connection counts per topic handle
        # Parameter changes other nodes (or the world) made since the last batch, in order: [name, value (None:
        # deleted)].
        self.params = params


class Link:
    """Frames to and from the grader. Every frame is written at once (nothing is lost if the node is killed)."""

    def __init__(self, read_fd: int, write_fd: int) -> None:
        self._reader = ch.FrameReader(read_fd, ch.GRADER_KINDS)
        self._wfd = write_fd
        self._lock = threading.Lock()
        self.frames_sent = 0
        # The moment of a batch of moments the node is at, until the grader has been told (a MOMENT frame goes out
        # in the same write as the next frame, or alone at exit).
        self.pending_moment: int | None = None

    def send(self, frame: bytes) -> None:
        try:
            with self._lock:
                if self.pending_moment is not None:
                    frame = ch.encode_moment(self.pending_moment) + frame
                    self.pending_moment = None
                ch.write_all(self._wfd, frame)
                self.frames_sent += 1
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
        self.send(ch.encode_json(kind, obj))

    def send_output(self, stream: int, data: bytes) -> None:
        for start in range(0, len(data), _OUTPUT_CHUNK):
            self.send(ch.encode_output(stream, data[start:start + _OUTPUT_CHUNK]))

    def send_message(self, kind: int, ident: int, data: bytes) -> None:
        self.send(ch.encode_id_bytes(kind, ident, data))

    def call(self, header: dict, request: bytes) -> tuple[dict, bytes]:
        """Send a CALL and read its REPLY: (the reply's header, the response bytes).

        The grader answers at once, before anything else, so only the thread holding the scheduler's token may call
        (no other thread reads the channel meanwhile)."""
        self.send(ch.encode_header_bytes(ch.CALL, header, request))
        try:
            head, response = ch.split_header_bytes(self._read(ch.REPLY))
            return ch.decode_json(head), response
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
            return Batch(t_ns=_int(header, "t_ns"), clock_ns=_int(header, "clock_ns"), deliveries=deliveries,
                         moments=moments, shutdown=None if shutdown is None else str(shutdown),
                         connections=_counts(header.get("connections") or {}),
                         params=_changes(header.get("params") or []))
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
