"""The moments part of the channel contract: a BATCH's later moments, the node's MOMENT answer, and the grader's
checks of it (a node that does not say which moment it stopped at, or names one the batch did not have, broke the
channel)."""
from __future__ import annotations

import os
import sys

import pytest

from grader.nodelib import import_roots
from grader.recording import default_catalog
from grader.runtime.node_link import NodeLink, ProtocolViolation

sys.path[:0] = [str(p) for p in import_roots("ros1")]
import rosgrade_channel as ch  # noqa: E402  (the node's own import of the channel module)
from rosgrade_node import link  # noqa: E402
from rosgrade_node.link import Link  # noqa: E402

CATALOG = default_catalog()


@pytest.fixture
def pipes():
    """(grader's NodeLink, node's Link) on two pipes."""
    to_grader_r, to_grader_w = os.pipe()
    to_node_r, to_node_w = os.pipe()
    yield (NodeLink(to_grader_r, to_node_w, CATALOG, silent_wall_s=5.0, output_cap=1 << 20),
           Link(to_node_r, to_grader_w))
    for fd in (to_grader_r, to_grader_w, to_node_r, to_node_w):
        os.close(fd)


def test_a_batch_splits_its_deliveries_between_its_own_time_and_its_later_moments(pipes) -> None:
    grader, node = pipes
    later = [(200, 200, [(1, b"b"), (2, b"c")]), (300, 300, []), (400, 400, [(1, b"d")])]
    grader.resume(100, 100, [(1, b"a")], None, later=later)
    batch = node.read_batch()
    assert (batch.t_ns, batch.clock_ns, batch.deliveries) == (100, 100, [(1, b"a")])
    assert [(m.t_ns, m.clock_ns, m.deliveries) for m in batch.moments] == later


def test_a_plain_batch_has_no_later_moments(pipes) -> None:
    grader, node = pipes
    grader.resume(100, 100, [(1, b"a")], None)
    assert node.read_batch().moments == []


@pytest.mark.parametrize("moments, says", [
    ([[200, 200, 2]], "more deliveries"),
    ([[200, 200]], "triples"),
    ([[200, 200, -1]], "non-negative"),
    ({"t": 1}, "triples"),
])
def test_a_batch_with_malformed_moments_is_a_channel_error(moments, says: str) -> None:
    payload = ch.encode_batch({"t_ns": 1, "clock_ns": 0, "moments": moments}, [(1, b"a")])[5:]
    header, deliveries = ch.decode_batch(payload)
    with pytest.raises(ch.ChannelError, match=says):
        link._moments(header["moments"], deliveries)


def test_the_moment_goes_out_in_the_same_write_as_the_nodes_next_frame(pipes) -> None:
    grader, node = pipes
    node.pending_moment = 3
    node.send(ch.encode_wait(None))
    data = os.read(grader._reader.fd, 1 << 16)
    assert data == ch.encode_moment(3) + ch.encode_wait(None)
    assert node.pending_moment is None and node.frames_sent == 1


def test_a_node_ending_at_a_moment_says_which_alone(pipes) -> None:
    grader, node = pipes
    node.send_pending_moment()  # nothing pending: nothing written
    node.pending_moment = 2
    node.send_pending_moment()
    assert os.read(grader._reader.fd, 1 << 16) == ch.encode_moment(2)


def test_events_after_a_moment_happen_at_its_time(pipes) -> None:
    grader, node = pipes
    seen: list[int] = []
    node.pending_moment = 2
    node.send_json(ch.INIT, {"name": "/n", "anonymous": False, "log_level": None, "disable_signals": False})
    node.send(ch.encode_wait(500))
    wake = grader.run_until_wait(100, lambda event: None, moments=3, at_moment=lambda i: seen.append(i) or 250)
    # the wake-up is checked against the moment's time too: one in its past costs a quantum from there
    assert seen == [2] and grader.state.init_ns == 250 and wake == 250 + ch.CALL_QUANTUM_NS


@pytest.mark.parametrize("frames, says", [
    ([ch.encode_wait(500)], "without saying first which moment"),
    ([ch.encode_moment(4), ch.encode_wait(500)], "MOMENT 4 of a batch of 3"),
    ([ch.encode_moment(0), ch.encode_wait(500)], "MOMENT 0 of a batch of 3"),
    ([ch.encode(ch.MOMENT, b"\x01"), ch.encode_wait(500)], "4-byte"),
    ([ch.encode_moment(2), ch.encode_moment(3), ch.encode_wait(500)], "a second one"),
])
def test_a_node_that_breaks_the_moment_contract_is_a_protocol_violation(pipes, frames, says: str) -> None:
    grader, node = pipes
    for frame in frames:
        ch.write_all(node._wfd, frame)
    with pytest.raises(ProtocolViolation, match=says):
        grader.run_until_wait(100, lambda event: None, moments=3, at_moment=lambda i: 100 * i)


def test_a_moment_in_a_batch_of_one_is_a_protocol_violation(pipes) -> None:
    grader, node = pipes
    ch.write_all(node._wfd, ch.encode_moment(1) + ch.encode_wait(None))
    with pytest.raises(ProtocolViolation, match="outside a batch"):
        grader.run_until_wait(100, lambda event: None)
