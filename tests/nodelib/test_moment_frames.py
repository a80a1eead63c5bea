"""The moments part of the channel contract: a BATCH's later moments and horizon, the node's MOMENT answers, what
ends a run of moments (on both sides, at the same frame), and the grader's checks (a node that does not say which
moment it is at, or goes on naming moments after it acted, broke the channel)."""
from __future__ import annotations

import os
import re
import struct
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
    grader.resume(100, 100, [(1, b"a")], None, later=later, until_ns=450, inert={3: True, 4: False})
    batch = node.read_batch()
    assert (batch.t_ns, batch.clock_ns, batch.deliveries) == (100, 100, [(1, b"a")])
    assert [(m.t_ns, m.clock_ns, m.deliveries) for m in batch.moments] == later
    assert batch.until_ns == 450 and batch.inert == {3: True, 4: False}


def test_a_batch_may_run_ahead_with_no_later_moment(pipes) -> None:
    """A node that only publishes gets no deliveries, yet may run its own wake-ups up to the horizon."""
    grader, node = pipes
    grader.resume(100, 100, [], None, until_ns=900, inert={})
    batch = node.read_batch()
    assert batch.moments == [] and batch.until_ns == 900


def test_a_plain_batch_has_no_later_moments(pipes) -> None:
    grader, node = pipes
    grader.resume(100, 100, [(1, b"a")], None)
    batch = node.read_batch()
    assert batch.moments == [] and batch.until_ns is None and batch.inert == {}


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


class _Ended(Exception):
    """Where the node library would end the node (os._exit) on a broken channel."""


@pytest.mark.parametrize("extra, says", [
    ({"moments": [[200, 200, 0]]}, "until must come with moments"),
    ({"moments": [[200, 200, 0]], "until": 150}, "at or after the batch's last time"),
    ({"until": 50}, "at or after"),
    ({"until": 300, "inert": {"3": "maybe"}}, '"any" or "same"'),
    ({"until": 300, "inert": {"x": "any"}}, "publisher handles"),
])
def test_a_batch_with_a_malformed_horizon_is_a_channel_error(pipes, monkeypatch, extra: dict, says: str) -> None:
    grader, node = pipes
    monkeypatch.setattr(link, "_fail", lambda exc: (_ for _ in ()).throw(_Ended(str(exc))))
    grader._send(ch.encode_batch({"t_ns": 100, "clock_ns": 0, **extra}, []))
    with pytest.raises(_Ended, match=re.escape(says)):
        node.read_batch()


def test_the_moment_goes_out_in_the_same_write_as_the_nodes_next_frame(pipes) -> None:
    grader, node = pipes
    node.pending_moment = 300
    node.send(ch.encode_wait(None))
    data = os.read(grader._reader.fd, 1 << 16)
    assert data == ch.encode_moment(300) + ch.encode_wait(None)
    assert node.pending_moment is None


def test_a_node_ending_at_a_moment_says_which_alone(pipes) -> None:
    grader, node = pipes
    node.send_pending_moment()  # nothing pending: nothing written
    node.pending_moment = 200
    node.send_pending_moment()
    assert os.read(grader._reader.fd, 1 << 16) == ch.encode_moment(200)


def test_events_after_a_moment_happen_at_its_time(pipes) -> None:
    grader, node = pipes
    seen: list[int] = []
    node.pending_moment = 250
    node.send_json(ch.INIT, {"name": "/n", "anonymous": False, "log_level": None, "disable_signals": False})
    node.send(ch.encode_wait(500))
    wake = grader.run_until_wait(100, lambda event: None, {}, lambda t: seen.append(t) or t, lambda: None)
    # the wake-up is checked against the moment's time too: one in its past costs a quantum from there
    assert seen == [250] and grader.state.init_ns == 250 and wake == 250 + ch.CALL_QUANTUM_NS


ADVERTISE = {"topic": "/cmd_vel", "type": "geometry_msgs/Twist", "md5sum": CATALOG.md5sum("geometry_msgs/Twist"),
             "queue_size": 1, "latch": False}


def _twist(x: float) -> bytes:
    return struct.pack("<6d", x, 0, 0, 0, 0, 0)


@pytest.mark.parametrize("steps, acts_at", [
    ([("log",), ("print",), ("publish", 9, _twist(5))], None),  # logs, prints, anything on an "any" publisher
    ([("publish", 8, _twist(0.2)), ("publish", 8, _twist(0.2))], None),  # the robot's command, repeated
    ([("publish", 8, _twist(0.2)), ("publish", 8, _twist(0.3))], 1),  # another command
    ([("log",), ("publish", 7, _twist(0.2))], 1),  # a publisher the batch does not call inert
    ([("print",), ("param",)], 1),  # anything but a log line, printed text or an inert message
])
def test_the_node_and_the_grader_agree_on_what_ends_a_run_of_moments(pipes, steps, acts_at) -> None:
    """The node goes on to its next moment only while nothing it sent matters; the grader takes the world back at
    the first frame that does. Both must draw that line at the same frame."""
    grader, node = pipes
    for ident in (7, 8, 9):
        node.send_json(ch.ADVERTISE, {**ADVERTISE, "id": ident})
    node.send_message(ch.PUBLISH, 8, _twist(0.2))  # the robot's command in force, before the batch
    node.send(ch.encode_wait(None))
    grader.run_until_wait(100, lambda event: None)
    node.begin_moments(200, {8: False, 9: True})
    node_acted = []
    for index, (what, *args) in enumerate(steps):
        if what == "log":
            node.send_json(ch.LOG, {"level": 2, "msg": "hi", "name": "/n", "file": "f.py", "function": "f",
                                    "line": 1})
        elif what == "print":
            node.send_output(1, b"hello\n")
        elif what == "publish":
            node.send_message(ch.PUBLISH, *args)
        else:
            node.send_json(ch.PARAM, {"op": ch.PARAM_SET, "name": "/p", "value": 1})
        if node.acted and not node_acted:
            node_acted.append(index)
    node.send(ch.encode_wait(None))
    grader_acted: list[int] = []
    events: list[object] = []
    grader.run_until_wait(200, events.append, {8: False, 9: True}, lambda t: t,
                          lambda: grader_acted.append(len(events)))
    expected = [] if acts_at is None else [acts_at]
    assert node_acted == expected
    assert grader_acted == expected  # on_act came after as many events as frames came before the acting one


@pytest.mark.parametrize("frames, says", [
    ([ch.encode_wait(500)], "without saying first which moment"),
    ([ch.encode(ch.MOMENT, b"\x01"), ch.encode_wait(500)], "8-byte"),
    ([ch.encode_moment(200), ch.encode(ch.PARAM, b'{"op":"set","name":"/p","value":1}'), ch.encode_moment(300)],
     "after the node acted"),
])
def test_a_node_that_breaks_the_moment_contract_is_a_protocol_violation(pipes, frames, says: str) -> None:
    grader, node = pipes
    for frame in frames:
        ch.write_all(node._wfd, frame)
    with pytest.raises(ProtocolViolation, match=says):
        grader.run_until_wait(100, lambda event: None, {}, lambda t: t, lambda: None)


def test_a_moment_in_a_plain_batch_is_a_protocol_violation(pipes) -> None:
    grader, node = pipes
    ch.write_all(node._wfd, ch.encode_moment(100) + ch.encode_wait(None))
    with pytest.raises(ProtocolViolation, match="outside a batch"):
        grader.run_until_wait(100, lambda event: None)
