"""The service part of the channel contract: CALL, SERVE, RESPOND and REPLY frames, their schemas, the BATCH's
service deliveries, and the grader's checks (a malformed frame is a protocol violation; a probe is answered at once
with the session's reply, a call goes to the session and is answered later)."""
from __future__ import annotations

import json
import os

import pytest

from grader.nodelib.common import rosgrade_channel as ch
from grader.recording import default_catalog
from grader.runtime import frames
from grader.runtime.node_link import (NodeLink, ProtocolViolation, ServiceAnswer, ServiceCall, ServiceOffer,
                                      ServiceReply)

CATALOG = default_catalog()
SPAWN_MD5 = "0b2d2e872a8e2887d5ed626f2bf2c561"  # turtlesim/Spawn's md5sum in ROS 1 noetic
SPAWN = {"service": "/spawn", "type": "turtlesim/Spawn", "md5sum": SPAWN_MD5, "probe": False, "id": 7, "seq": 1}
PROBE = {"service": "/spawn", "type": "*", "md5sum": "*", "probe": True, "id": 0, "seq": 0}
SERVE = {"id": 3, "service": "/spawn", "type": "turtlesim/Spawn", "md5sum": SPAWN_MD5}


def spawn_request(name: str = "") -> bytes:
    request_class = CATALOG.message_class("turtlesim/SpawnRequest")
    return CATALOG.encode("turtlesim/SpawnRequest", request_class(x=1.0, y=2.0, theta=0.5, name=name))


def test_the_grader_knows_turtlesims_srv_md5sums() -> None:
    assert CATALOG.service_md5sum("turtlesim/Spawn") == SPAWN_MD5


def test_call_and_reply_frames_round_trip_header_and_bytes() -> None:
    frame = ch.encode_header_bytes(ch.CALL, SPAWN, b"\x01\x02")
    assert frame[4] == ch.CALL
    header, data = ch.split_header_bytes(frame[5:])
    assert json.loads(header) == SPAWN and data == b"\x01\x02"


@pytest.mark.parametrize("payload, says", [(b"\x01", "shorter"), (b"\xff\x00\x00\x00{}", "runs past")])
def test_a_cut_call_or_reply_is_a_channel_error(payload: bytes, says: str) -> None:
    with pytest.raises(ch.ChannelError, match=says):
        ch.split_header_bytes(payload)


@pytest.mark.parametrize("header", [SPAWN, PROBE])
def test_the_call_headers_the_node_library_sends_are_accepted(header: dict) -> None:
    assert frames.parse(ch.CALL, json.dumps(header).encode()).model_dump() == header


@pytest.mark.parametrize("header, says", [
    ({**SPAWN, "md5sum": "abc"}, "'md5sum'"),
    ({**SPAWN, "probe": 1}, "'probe'"),
    ({**SPAWN, "extra": 1}, "'extra'"),
    ({k: v for k, v in SPAWN.items() if k != "service"}, "'service'"),
    ({k: v for k, v in SPAWN.items() if k != "seq"}, "'seq'"),
    ({**SPAWN, "id": -1}, "'id'"),
    ({**SPAWN, "service": "/" + "s" * 300}, "'service'"),
])
def test_a_call_header_off_its_schema_is_a_frame_error_naming_the_field(header: dict, says: str) -> None:
    with pytest.raises(frames.FrameError, match=says):
        frames.parse(ch.CALL, json.dumps(header).encode())


class Channel:
    """A NodeLink on pipes, with the node's ends: write frames as a node, read what the grader answered."""

    def __init__(self) -> None:
        self.to_grader_r, self.to_grader_w = os.pipe()
        self.to_node_r, self.to_node_w = os.pipe()
        self.link = NodeLink(self.to_grader_r, self.to_node_w, CATALOG, silent_wall_s=5.0,
                             output_cap=1 << 20)
        self.calls: list[ServiceCall] = []

    def close(self) -> None:
        for fd in (self.to_grader_r, self.to_grader_w, self.to_node_r, self.to_node_w):
            os.close(fd)

    def step(self, *node_frames: bytes, reply: ServiceReply = ServiceReply(ch.SERVICE_OK)) -> int | None:
        """The node sends ``node_frames`` then WAIT; every call is answered with ``reply``."""
        for frame in (*node_frames, ch.encode_json(ch.WAIT, {"wake_ns": 50})):
            ch.write_all(self.to_grader_w, frame)

        def sink(event: object) -> ServiceReply | None:
            if isinstance(event, ServiceCall):
                self.calls.append(event)
                return reply
            return None

        return self.link.run_until_wait(10, sink)

    def replies(self) -> list[tuple[dict, bytes]]:
        reader = ch.FrameReader(self.to_node_r, ch.GRADER_KINDS)
        os.set_blocking(self.to_node_r, False)
        found = []
        while True:
            try:
                kind, payload = reader.read()
            except BlockingIOError:
                return found
            assert kind == ch.REPLY
            header, data = ch.split_header_bytes(payload)
            found.append((json.loads(header), data))


@pytest.fixture
def channel():
    made = Channel()
    yield made
    made.close()


def test_a_call_reaches_the_session_with_its_handle_and_number_and_gets_no_reply_at_once(channel: Channel) -> None:
    request = spawn_request("t2")
    assert channel.step(ch.encode_header_bytes(ch.CALL, SPAWN, request), reply=None) is not None
    assert channel.calls == [ServiceCall("/spawn", "turtlesim/Spawn", SPAWN_MD5, False, request, 7, 1)]
    assert channel.replies() == []


def test_a_probe_is_answered_at_once(channel: Channel) -> None:
    channel.step(ch.encode_header_bytes(ch.CALL, PROBE, b""), reply=ServiceReply(ch.SERVICE_UNAVAILABLE))
    assert channel.calls[0].probe
    assert channel.replies() == [({"status": "unavailable", "error": ""}, b"")]


def test_a_call_of_a_srv_type_the_grader_does_not_know_is_passed_on_unchecked(channel: Channel) -> None:
    header = {**SPAWN, "service": "/static_map", "type": "nav_msgs/GetMap", "md5sum": "6" * 32}
    channel.step(ch.encode_header_bytes(ch.CALL, header, b"\x05"), reply=None)
    assert channel.calls[0].type == "nav_msgs/GetMap" and channel.calls[0].request == b"\x05"


def test_a_served_service_is_offered_and_its_answers_checked(channel: Channel) -> None:
    events: list = []
    response = CATALOG.encode("turtlesim/SpawnResponse", CATALOG.message_class("turtlesim/SpawnResponse")(name="t2"))
    for frame in (ch.encode_json(ch.SERVE, SERVE),
                  ch.encode_header_bytes(ch.RESPOND, {"id": 3, "seq": 1, "status": "ok", "error": ""}, response),
                  ch.encode_json(ch.WAIT, {"wake_ns": 50})):
        ch.write_all(channel.to_grader_w, frame)
    channel.link.run_until_wait(10, events.append)
    offer, answer = events
    assert isinstance(offer, ServiceOffer) and offer.endpoint.topic == "/spawn" and offer.endpoint.registered_ns == 10
    assert answer == ServiceAnswer(offer.endpoint, 1, "ok", "", response)


@pytest.mark.parametrize("respond, data, says", [
    ({"id": 4, "seq": 1, "status": "ok", "error": ""}, b"", "unknown or withdrawn service handle 4"),
    ({"id": 3, "seq": 1, "status": "ok", "error": ""}, b"\x01", "is not a valid turtlesim/Spawn response"),
    ({"id": 3, "seq": 1, "status": "failed", "error": "x"}, b"\x01", "RESPOND failed on /spawn carries 1 bytes"),
    ({"id": 3, "seq": 1, "status": "unavailable", "error": ""}, b"", "'status'"),
])
def test_a_malformed_answer_is_a_protocol_violation(channel: Channel, respond: dict, data: bytes, says: str) -> None:
    with pytest.raises(ProtocolViolation, match=says):
        channel.step(ch.encode_json(ch.SERVE, SERVE), ch.encode_header_bytes(ch.RESPOND, respond, data))


def test_a_service_offered_twice_under_one_handle_is_a_protocol_violation(channel: Channel) -> None:
    with pytest.raises(ProtocolViolation, match="handle 3, which the node already uses"):
        channel.step(ch.encode_json(ch.SERVE, SERVE), ch.encode_json(ch.SERVE, {**SERVE, "service": "/other"}))


def test_service_deliveries_round_trip_in_a_batch() -> None:
    deliveries = [(3, b"req", (1, ch.SERVICE_REQUEST, "")), (5, b"", (2, ch.SERVICE_FAILED, "no")), (9, b"msg")]
    frame = ch.encode_batch({"t_ns": 1, "clock_ns": 0}, deliveries)
    header, decoded = ch.decode_batch(frame[5:])
    assert header == {"t_ns": 1, "clock_ns": 0} and decoded == deliveries


@pytest.mark.parametrize("svc", [[[5, 1, "ok", ""]], [[0, -1, "ok", ""]], [[0, 1, "ok"]], "x"])
def test_a_malformed_batch_svc_is_a_channel_error(svc) -> None:
    head = json.dumps({"t_ns": 1, "clock_ns": 0, "svc": svc}).encode()
    payload = len(head).to_bytes(4, "little") + head + (3).to_bytes(4, "little") + (1).to_bytes(4, "little") + b"x"
    with pytest.raises(ch.ChannelError, match="svc"):
        ch.decode_batch(payload)


@pytest.mark.parametrize("header, request_bytes, says", [
    (PROBE, b"\x00", "probe of /spawn carries 1 request bytes"),
    ({**SPAWN, "md5sum": "0" * 32}, spawn_request(), "md5sum for service type turtlesim/Spawn"),
    (SPAWN, b"\x00\x00", "is not a valid turtlesim/Spawn request"),
    (SPAWN, spawn_request() + b"\x00", "is not a valid turtlesim/Spawn request"),
    ({**SPAWN, "service": "spawn"}, spawn_request(), "invalid service name 'spawn'"),
    ({**SPAWN, "service": "/a b"}, spawn_request(), "invalid service name"),
])
def test_a_malformed_call_is_a_protocol_violation(channel: Channel, header: dict, request_bytes: bytes,
                                                  says: str) -> None:
    with pytest.raises(ProtocolViolation, match=says):
        channel.step(ch.encode_header_bytes(ch.CALL, header, request_bytes))
    assert channel.calls == []


def test_a_call_header_that_is_not_json_is_a_protocol_violation(channel: Channel) -> None:
    with pytest.raises(ProtocolViolation, match="CALL frame"):
        channel.step(ch.encode(ch.CALL, b"\x03\x00\x00\x00[1]"))
