"""The channel contract: BATCH frames round-trip, and every node frame kind is checked against its schema."""
from __future__ import annotations

import json

import pytest

from grader.nodelib.common import rosgrade_channel as ch
from grader.runtime import frames

LOG = {"level": 2, "msg": "hi", "name": "/n", "file": "n.py", "function": "main", "line": 3}
REGISTER = {"id": 1, "topic": "/chatter", "type": "std_msgs/String", "md5sum": "992ce8a1687cec8c8bd883ec73ca41d1",
            "queue_size": 10, "latch": False}


def _payload(frame: bytes) -> bytes:
    return frame[5:]


def test_batch_round_trip_keeps_header_and_deliveries_in_order():
    deliveries = [(7, b"\x01\x02"), (3, b""), (7, bytes(range(256)))]
    frame = ch.encode_batch({"t_ns": 5, "clock_ns": 0, "shutdown": "signal-2"}, deliveries)
    assert frame[4] == ch.BATCH
    header, got = ch.decode_batch(_payload(frame))
    assert header == {"t_ns": 5, "clock_ns": 0, "shutdown": "signal-2"}
    assert got == deliveries


@pytest.mark.parametrize("payload, says", [
    (b"\x01", "shorter"),
    (b"\xff\x00\x00\x00{}", "header runs past"),
    (b"\x02\x00\x00\x00{}\x01\x00", "cut short"),
    (b"\x02\x00\x00\x00{}\x01\x00\x00\x00\x09\x00\x00\x00ab", "runs past"),
])
def test_malformed_batch_is_a_channel_error(payload, says):
    with pytest.raises(ch.ChannelError, match=says):
        ch.decode_batch(payload)


def test_deeply_nested_json_is_a_channel_error_not_a_recursion_error():
    with pytest.raises(ch.ChannelError):
        ch.decode_json(b"[" * 100_000 + b"]" * 100_000)


@pytest.mark.parametrize("kind, obj", [
    (ch.LOG, LOG), (ch.ADVERTISE, REGISTER), (ch.SUBSCRIBE, {**REGISTER, "queue_size": None}),
    (ch.SUBSCRIBE, {**REGISTER, "qos": ["BEST_EFFORT", "VOLATILE"]}),
    (ch.WAIT, {"wake_ns": None, "busy": False}), (ch.WAIT, {"wake_ns": 10, "busy": True}), (ch.UNREGISTER, {"id": 4}),
    (ch.INIT, {"name": "/n", "anonymous": False, "log_level": None, "disable_signals": True}),
    (ch.EXCEPTION, {"type": "ValueError", "message": "m", "where": "callback",
                    "frames": [{"file": "n.py", "line": None, "function": "f", "text": ""}]}),
])
def test_frames_the_node_library_sends_are_accepted(kind, obj):
    assert frames.parse(kind, json.dumps(obj).encode()).model_dump(exclude_unset=True) == obj


@pytest.mark.parametrize("kind, obj, says", [
    (ch.LOG, {**LOG, "line": "3"}, "'line'"),
    (ch.LOG, {**LOG, "extra": 1}, "'extra'"),
    (ch.LOG, {k: v for k, v in LOG.items() if k != "msg"}, "'msg'"),
    (ch.WAIT, {"wake_ns": -1}, "'wake_ns'"),
    (ch.WAIT, {"wake_ns": True}, "'wake_ns'"),
    (ch.ADVERTISE, {**REGISTER, "id": 1 << 40}, "'id'"),
    (ch.ADVERTISE, {**REGISTER, "md5sum": "x"}, "'md5sum'"),
    (ch.ADVERTISE, {**REGISTER, "topic": "/" + "a" * 300}, "'topic'"),
    (ch.EXCEPTION, {"type": "E", "message": "m", "where": "uncaught", "frames": {"a": 1}}, "'frames'"),
    (ch.EXCEPTION, {"type": "E", "message": "m", "where": "uncaught", "frames": [{}] * 51}, "'frames"),
])
def test_a_field_off_its_schema_is_a_frame_error_naming_it(kind, obj, says):
    with pytest.raises(frames.FrameError, match=says):
        frames.parse(kind, json.dumps(obj).encode())


@pytest.mark.parametrize("payload", [b"[1]", b"\xff", b"{", b"[" * 5000 + b"]" * 5000, b" " * (ch.MAX_JSON_BYTES + 1)])
def test_payloads_that_are_not_one_json_object_are_frame_errors(payload):
    with pytest.raises(frames.FrameError):
        frames.parse(ch.LOG, payload)


@pytest.mark.parametrize("t_ns,clock_ns", [(0, 0), (5, 0), (2_000_000_001, 2_000_000_000), (2**63 - 1, 10)])
def test_plain_batch_header_is_the_json_module_s_bytes(t_ns: int, clock_ns: int) -> None:
    header = {"t_ns": t_ns, "clock_ns": clock_ns}
    payload = _payload(ch.encode_batch(header, [(1, b"ab")]))
    head = json.dumps(header, separators=(",", ":")).encode()
    assert payload[4:4 + len(head)] == head
    assert ch.decode_batch(payload) == (header, [(1, b"ab")])


@pytest.mark.parametrize("busy", [False, True])
@pytest.mark.parametrize("wake", [None, 0, 10, 2**63])
def test_wait_frames_read_back_as_written(wake, busy: bool) -> None:
    payload = _payload(ch.encode_wait(wake, busy))
    assert json.loads(payload) == ({"wake_ns": wake, "busy": True} if busy else {"wake_ns": wake})
    assert ch.plain_wait(payload) == (True, wake, busy)


@pytest.mark.parametrize("payload", [b'{"wake_ns": 5}', b'{"wake_ns":-1}', b'{"wake_ns":05}', b'{"wake_ns":1.5}',
                                     b'{"wake_ns":5,"x":1}', b'{"wake_ns":5,"busy":false}', b'{"wake_ns":true}',
                                     b'{"wake_ns":5}\n'])
def test_anything_else_in_a_wait_goes_to_the_schema(payload: bytes) -> None:
    assert ch.plain_wait(payload) == (False, None, False)
