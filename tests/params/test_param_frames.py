"""The PARAM frame: its schema, and the grader's checks of it (a bad one is the node's protocol violation, a node that
floods the server is stopped, a good one reaches the session as a ParamChange); BATCH headers carry the changes."""
from __future__ import annotations

import json
import os

import pytest

from grader.nodelib.common import rosgrade_channel as ch
from grader.recording import default_catalog
from grader.runtime import frames
from grader.runtime.node_link import (MAX_PARAM_BYTES, NodeLink, ParamChange, ParamLimitExceeded,
                                      ProtocolViolation)


class Channel:
    """A NodeLink on pipes: write frames as a node (small: they fit the pipe), collect the events it passes on."""

    def __init__(self) -> None:
        self.to_grader_r, self.to_grader_w = os.pipe()
        self.to_node_r, self.to_node_w = os.pipe()
        self.link = NodeLink(self.to_grader_r, self.to_node_w, default_catalog(), silent_wall_s=5.0,
                             output_cap=1 << 20)
        self.events: list[object] = []

    def close(self) -> None:
        for fd in (self.to_grader_r, self.to_grader_w, self.to_node_r, self.to_node_w):
            os.close(fd)

    def step(self, *params: dict) -> None:
        for frame in (*(ch.encode_json(ch.PARAM, p) for p in params), ch.encode_json(ch.WAIT, {"wake_ns": 50})):
            ch.write_all(self.to_grader_w, frame)
        self.link.run_until_wait(10, self.events.append)


@pytest.fixture
def channel():
    made = Channel()
    yield made
    made.close()


@pytest.mark.parametrize("obj", [
    {"op": "set", "name": "/a", "value": 1},
    {"op": "set", "name": "/a/b", "value": {"c": [1, 2.5, "x", True, {"d": -1}]}},
    {"op": "set", "name": "/", "value": {"a": 1}},
    {"op": "delete", "name": "/a"},
])
def test_the_param_frames_rospy_sends_are_accepted(obj: dict) -> None:
    frame = frames.parse(ch.PARAM, json.dumps(obj).encode())
    assert (frame.op, frame.name, frame.value) == (obj["op"], obj["name"], obj.get("value"))


@pytest.mark.parametrize(("obj", "says"), [
    ({"op": "put", "name": "/a", "value": 1}, "field 'op'"),
    ({"op": "set", "name": "/a"}, "a set needs a value that is not null"),
    ({"op": "set", "name": "/a", "value": None}, "a set needs a value that is not null"),
    ({"op": "delete", "name": "/a", "value": 3}, "a delete takes none"),
    ({"op": "set", "name": 7, "value": 1}, "field 'name'"),
    ({"op": "set", "name": "/" + "a" * ch.MAX_NAME_CHARS, "value": 1}, "field 'name'"),
    ({"op": "set", "name": "/a", "value": 1, "by": "/other"}, "field 'by'"),
])
def test_a_param_frame_off_its_schema_is_a_frame_error(obj: dict, says: str) -> None:
    with pytest.raises(frames.FrameError, match="PARAM frame") as err:
        frames.parse(ch.PARAM, json.dumps(obj).encode())
    assert says in str(err.value)


def test_param_is_a_json_kind_a_node_may_send_and_the_protocol_moved_on() -> None:
    assert ch.PARAM in ch.NODE_KINDS and ch.PARAM in ch.JSON_KINDS and ch.PARAM not in ch.GRADER_KINDS
    assert ch.KIND_NAMES[ch.PARAM] == "PARAM" and ch.PROTOCOL >= 5  # 5 brought PARAM


def test_a_set_and_a_delete_reach_the_session_in_order(channel: Channel) -> None:
    channel.step({"op": "set", "name": "/a/b", "value": [1, 2]}, {"op": "delete", "name": "/c"})
    assert channel.events == [ParamChange("/a/b", [1, 2]), ParamChange("/c", None)]


@pytest.mark.parametrize(("obj", "says"), [
    ({"op": "set", "name": "a/b", "value": 1}, "invalid parameter name 'a/b'"),
    ({"op": "set", "name": "/a b", "value": 1}, "invalid parameter name"),
    ({"op": "set", "name": "/", "value": 5}, "root of the parameter tree to a value that is not a dict"),
    ({"op": "delete", "name": "/"}, "root of the parameter tree, which cannot be deleted"),
    ({"op": "set", "name": "/a"}, "PARAM frame: Value error"),
])
def test_a_bad_param_frame_is_a_protocol_violation(channel: Channel, obj: dict, says: str) -> None:
    with pytest.raises(ProtocolViolation) as err:
        channel.step(obj)
    assert says in str(err.value)
    assert channel.events == []


def test_a_node_past_its_parameter_budget_is_stopped(channel: Channel) -> None:
    big = {"op": "set", "name": "/big", "value": "x" * 30_000}  # well within a pipe's buffer per step
    with pytest.raises(ParamLimitExceeded, match="changed parameters by more than"):
        for _ in range(MAX_PARAM_BYTES // 30_000 + 1):
            channel.step(big)


def test_a_batch_header_carries_the_changes_in_order_past_the_json_frame_cap() -> None:
    changes = [["/a", {"b": "y" * ch.MAX_JSON_BYTES}], ["/a/b", None]]
    header, _ = ch.decode_batch(ch.encode_batch({"t_ns": 1, "clock_ns": 0, "params": changes}, [])[5:])
    assert header["params"] == changes


def test_resume_sends_the_changes_only_when_there_are_some(channel: Channel) -> None:
    channel.link.resume(20, 10, [], None, params=[("/a", 1), ("/b", None)])
    channel.link.resume(30, 30, [], None, params=[])
    reader = ch.FrameReader(channel.to_node_r, ch.GRADER_KINDS)
    first, second = (ch.decode_batch(reader.read()[1])[0] for _ in range(2))
    assert first["params"] == [["/a", 1], ["/b", None]] and "params" not in second
