"""Truncated, damaged and foreign files: a clear RecordingError, or what could be read plus why it stops."""
from __future__ import annotations

import os
import random
import sqlite3
from pathlib import Path

import pytest
from mcap.reader import make_reader

from grader.recording import Recording, RecordingError
from recording_helpers import Run, make_run, record

UNREADABLE = r"is not a readable recording: "


@pytest.fixture(scope="module")
def chunked(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A recording with many small chunks, so that a cut keeps the chunks before it."""
    return record(tmp_path_factory.mktemp("chunked") / "run.mcap", make_run(), chunk_size=2048)


def _write(path: Path, data: bytes) -> Path:
    path.write_bytes(data)
    return path


@pytest.mark.parametrize("cut", [8, 12, 30, 200])
def test_cut_before_any_message_is_an_error(tmp_path: Path, chunked: Path, cut: int) -> None:
    path = _write(tmp_path / "cut.mcap", chunked.read_bytes()[:cut])
    with pytest.raises(RecordingError, match=UNREADABLE + r"truncated \(the file ends inside a record\)"):
        Recording.open(path)


@pytest.mark.parametrize("fraction", [0.3, 0.5, 0.8])
def test_cut_midway_keeps_a_prefix_and_says_truncated(tmp_path: Path, chunked: Path, run: Run, fraction: float) -> None:
    data = chunked.read_bytes()
    recording = Recording.open(_write(tmp_path / "cut.mcap", data[: int(len(data) * fraction)]))
    assert recording.truncated is not None and recording.truncated.startswith("truncated")
    odom = recording.odometry()
    assert 0 < len(odom) < len(run.odometry)
    assert odom.x.tolist() == [s.position[0] for s in run.odometry[: len(odom)]]
    assert recording.metadata["rosgrade"]["robot"] == "turtlebot3_waffle"  # written first, so it survives
    assert "rosgrade.run" not in recording.metadata  # written at the end, so it is lost


@pytest.mark.parametrize("cut", [1, 8, 100])
def test_cut_in_the_summary_keeps_every_message(tmp_path: Path, chunked: Path, run: Run, cut: int) -> None:
    recording = Recording.open(_write(tmp_path / "cut.mcap", chunked.read_bytes()[:-cut]))
    assert recording.truncated is not None
    assert len(recording.odometry()) == len(run.odometry)


def test_strict_open_refuses_a_truncated_file(tmp_path: Path, chunked: Path) -> None:
    data = chunked.read_bytes()
    path = _write(tmp_path / "cut.mcap", data[: len(data) // 2])
    with pytest.raises(RecordingError, match=UNREADABLE + "truncated"):
        Recording.open(path, allow_truncated=False)


def test_flipped_byte_in_a_chunk_is_reported_as_damage(tmp_path: Path, chunked: Path) -> None:
    data = bytearray(chunked.read_bytes())
    with open(chunked, "rb") as f:
        summary = make_reader(f).get_summary()
    assert summary is not None
    chunk = summary.chunk_indexes[3]
    data[chunk.chunk_start_offset + chunk.chunk_length // 2] ^= 0xFF
    recording = Recording.open(_write(tmp_path / "flip.mcap", bytes(data)))
    assert recording.truncated is not None and recording.truncated.startswith("damaged (a chunk fails its checksum)")


def test_damaged_first_chunk_is_an_error(tmp_path: Path, chunked: Path) -> None:
    data = bytearray(chunked.read_bytes())
    with open(chunked, "rb") as f:
        summary = make_reader(f).get_summary()
    assert summary is not None
    chunk = summary.chunk_indexes[0]
    data[chunk.chunk_start_offset + chunk.chunk_length // 2] ^= 0xFF
    with pytest.raises(RecordingError, match=UNREADABLE + "damaged"):
        Recording.open(_write(tmp_path / "flip.mcap", bytes(data)))


def test_record_length_beyond_the_file_is_refused(tmp_path: Path, chunked: Path) -> None:
    data = bytearray(chunked.read_bytes()[:200])
    data[9:17] = (1 << 40).to_bytes(8, "little")  # the Header record claims a terabyte
    with pytest.raises(RecordingError, match=UNREADABLE + "damaged"):
        Recording.open(_write(tmp_path / "huge.mcap", bytes(data)))


_NOISE = random.Random(20261121)  # seeded: the same garbage (and the same test ids) on every run and worker


@pytest.mark.parametrize(
    "name,data,match",
    [
        ("garbage.mcap", _NOISE.randbytes(4096), "not an MCAP file, a ROS 1 bag or a ROS 2 bag"),
        ("text.bag", b"hello world\n", "not an MCAP file, a ROS 1 bag or a ROS 2 bag"),
        ("empty.mcap", b"", "the file is empty"),
        ("magic_only.mcap", b"\x89MCAP0\r\n", "truncated"),
        ("bad.bag", b"#ROSBAG V2.0\n" + bytes(100), ""),
        ("bad.mcap", b"\x89MCAP0\r\n" + _NOISE.randbytes(500), ""),
    ],
    ids=["garbage.mcap", "text.bag", "empty.mcap", "magic_only.mcap", "bad.bag", "bad.mcap"],
)
def test_garbage_is_an_error(tmp_path: Path, name: str, data: bytes, match: str) -> None:
    with pytest.raises(RecordingError, match=UNREADABLE + match):
        Recording.open(_write(tmp_path / name, data))


def test_missing_path_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(RecordingError, match=UNREADABLE + "no such file or directory"):
        Recording.open(tmp_path / "nope.mcap")


def test_bag_with_wrong_suffix_says_how_to_read_it(tmp_path: Path) -> None:
    with pytest.raises(RecordingError, match=r"looks like a rosbag1 file; name it \*\.bag"):
        Recording.open(_write(tmp_path / "run.dat", b"#ROSBAG V2.0\n" + bytes(100)))


def test_folder_that_is_not_a_bag_is_an_error(tmp_path: Path) -> None:
    (tmp_path / "notabag").mkdir()
    with pytest.raises(RecordingError, match=UNREADABLE):
        Recording.open(tmp_path / "notabag")


def test_sqlite_file_that_is_not_a_bag_is_an_error(tmp_path: Path) -> None:
    with sqlite3.connect(tmp_path / "other.db3") as db:
        db.execute("create table t (x int)")
    with pytest.raises(RecordingError, match=UNREADABLE):
        Recording.open(tmp_path / "other.db3")
