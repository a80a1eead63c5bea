"""A BATCH names who published each node's message it delivers (``from``), so the node's rospy can keep one connection
per publisher (its thread, queue and latched message); the world's messages carry no source."""
from __future__ import annotations

import json
import struct
import sys

import pytest

from grader.nodelib import import_roots

sys.path[:0] = [str(p) for p in import_roots("ros1")]
import rosgrade_channel as ch  # noqa: E402  (the node's own import of the channel module)


def test_sources_round_trip_beside_the_worlds_deliveries() -> None:
    deliveries = [(3, b"world"), (3, b"mine", ("/talker", True)), (4, b"other", ("/relay", False))]
    header, got = ch.decode_batch(ch.encode_batch({"t_ns": 7, "clock_ns": 0}, deliveries)[5:])
    assert header == {"t_ns": 7, "clock_ns": 0}
    assert got == deliveries


def test_a_batch_without_sources_keeps_the_plain_header() -> None:
    frame = ch.encode_batch({"t_ns": 7, "clock_ns": 0}, [(3, b"world")])
    assert b'{"t_ns":7,"clock_ns":0}' in frame and b"from" not in frame


@pytest.mark.parametrize("source", [[1, "/talker", True], [0, 5, True], [0, "/talker", 1], [0, "/talker"], "x"])
def test_a_malformed_source_is_a_channel_error(source) -> None:
    head = json.dumps({"t_ns": 1, "clock_ns": 0, "from": [source]}).encode()
    payload = struct.pack("<I", len(head)) + head + struct.pack("<II", 3, 1) + b"a"
    with pytest.raises(ch.ChannelError, match="BATCH from"):
        ch.decode_batch(payload)
