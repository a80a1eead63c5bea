"""Read our MCAP with an independent decoder (mcap + mcap_ros1's genpy) and compare every field exactly."""
from __future__ import annotations

import struct
from pathlib import Path
from typing import Any

import pytest
from mcap.reader import make_reader
from mcap_ros1.decoder import DecoderFactory

from recording_helpers import BASE_FRAME, Run
from sim.samples import GroundTruthSample, OdometrySample


def _bits(*values: float) -> bytes:
    """Floats compared bit for bit (-0.0 and 0.0 differ)."""
    return struct.pack(f"<{len(values)}d", *values)


@pytest.fixture(scope="module")
def decoded(recorded: Path) -> dict[tuple[str, str], list[tuple[int, Any]]]:
    out: dict[tuple[str, str], list[tuple[int, Any]]] = {}
    with open(recorded, "rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        for _, channel, message, msg in reader.iter_decoded_messages(log_time_order=True):
            out.setdefault((channel.topic, channel.metadata["callerid"]), []).append((message.log_time, msg))
    return out


def _check_odometry(
    msg: Any,
    seq: int,
    frames: tuple[str, str],
    s: OdometrySample | GroundTruthSample,
    pose_cov: tuple[float, ...],
    twist_cov: tuple[float, ...],
) -> None:
    assert (msg.header.seq, msg.header.stamp.secs, msg.header.stamp.nsecs) == (seq, s.t_ns // 10**9, s.t_ns % 10**9)
    assert (msg.header.frame_id, msg.child_frame_id) == frames
    p, q = msg.pose.pose.position, msg.pose.pose.orientation
    assert _bits(p.x, p.y, p.z, q.x, q.y, q.z, q.w) == _bits(*s.position, *s.orientation)
    v, w = msg.twist.twist.linear, msg.twist.twist.angular
    assert _bits(v.x, v.y, v.z, w.x, w.y, w.z) == _bits(*s.linear, *s.angular)
    assert _bits(*msg.pose.covariance) == _bits(*pose_cov)
    assert _bits(*msg.twist.covariance) == _bits(*twist_cov)


def test_odometry_fields_exact(decoded: dict, run: Run) -> None:
    got = decoded[("/odom", "/gazebo")]
    assert len(got) == len(run.odometry)
    for seq, ((t_ns, msg), s) in enumerate(zip(got, run.odometry)):
        assert t_ns == s.t_ns
        _check_odometry(msg, seq, (s.frame_id, s.child_frame_id), s, s.pose_covariance, s.twist_covariance)


def test_ground_truth_fields_exact(decoded: dict, run: Run) -> None:
    got = decoded[("/ground_truth/odom", "/gazebo")]
    assert len(got) == len(run.ground_truth)
    zero = (0.0,) * 36
    for seq, ((t_ns, msg), s) in enumerate(zip(got, run.ground_truth)):
        assert t_ns == s.t_ns
        _check_odometry(msg, seq, ("world", BASE_FRAME), s, zero, zero)


def test_tf_fields_exact(decoded: dict, run: Run) -> None:
    got = decoded[("/tf", "/gazebo")]
    assert len(got) == len(run.transforms)
    for seq, ((t_ns, msg), s) in enumerate(zip(got, run.transforms)):
        (tr,) = msg.transforms
        assert t_ns == s.t_ns
        assert (tr.header.seq, tr.header.stamp.to_nsec()) == (seq, s.t_ns)
        assert (tr.header.frame_id, tr.child_frame_id) == (s.frame_id, s.child_frame_id)
        v, r = tr.transform.translation, tr.transform.rotation
        assert _bits(v.x, v.y, v.z, r.x, r.y, r.z, r.w) == _bits(*s.translation, *s.rotation)


@pytest.mark.parametrize("callerid", ["/mover", "/rosgrade_driver"])
def test_command_fields_exact(decoded: dict, run: Run, callerid: str) -> None:
    expected = [c for c in run.commands if c.callerid == callerid]
    got = decoded[("/cmd_vel", callerid)]
    assert [t for t, _ in got] == [c.t_ns for c in expected]
    for (_, msg), c in zip(got, expected):
        v, w = msg.linear, msg.angular
        assert _bits(v.x, v.y, v.z, w.x, w.y, w.z) == _bits(*c.linear, *c.angular)


def test_log_fields_exact(decoded: dict, run: Run) -> None:
    got = decoded[("/rosout", "/mover")]
    assert len(got) == len(run.logs)
    for seq, ((t_ns, msg), line) in enumerate(zip(got, run.logs)):
        assert t_ns == line.t_ns == msg.header.stamp.to_nsec()
        assert msg.header.seq == seq
        assert (msg.level, msg.name, msg.msg) == (line.level, "/mover", line.msg)
        assert (msg.file, msg.function, msg.line) == ("mover.py", "main", 12)
        assert list(msg.topics) == ["/cmd_vel", "/rosout"]


@pytest.mark.parametrize("stream", ["stdout", "stderr"])
def test_output_fields_exact(decoded: dict, run: Run, stream: str) -> None:
    got = decoded[(f"/rosgrade/{stream}", "/mover")]
    assert [(t, m.data) for t, m in got] == getattr(run, stream)
