"""Recorder: the MCAP layout of the contract, deterministic bytes, metadata, misuse errors, size cap."""
from __future__ import annotations

from pathlib import Path

import pytest
from mcap.reader import make_reader
from mcap.records import Channel, Header, Message, Metadata, Schema, Statistics
from mcap.stream_reader import StreamReader
from rosbags.typesys.store import Typestore

from grader import __version__
from grader.recording import Recorder, Recording, RecordingError, twist_bytes
from recording_helpers import METADATA, Run, make_run, record

TWIST = twist_bytes((0.1, 0.0, 0.0), (0.0, 0.0, 0.2))


def _records(path: Path) -> list[object]:
    with open(path, "rb") as f:
        return list(StreamReader(f, validate_crcs=True).records)


def test_header_profile_and_library(recorded: Path) -> None:
    with open(recorded, "rb") as f:
        header = make_reader(f).get_header()
    assert header.profile == "ros1"
    assert header.library == f"rosgrade {__version__}"


def test_schema_and_message_encodings(recorded: Path) -> None:
    with open(recorded, "rb") as f:
        summary = make_reader(f).get_summary()
    assert summary is not None
    assert {s.encoding for s in summary.schemas.values()} == {"ros1msg"}
    assert {c.message_encoding for c in summary.channels.values()} == {"ros1"}


def test_one_schema_per_type_with_rosbags_text(recorded: Path, ros1_store: Typestore) -> None:
    schemas = [r for r in _records(recorded) if isinstance(r, Schema)]
    names = [s.name for s in schemas]
    # the summary repeats them; the data section holds each once
    assert sorted(set(names)) == sorted(
        ["nav_msgs/Odometry", "tf2_msgs/TFMessage", "geometry_msgs/Twist", "rosgraph_msgs/Log", "std_msgs/String"]
    )
    for schema in schemas:
        package, name = schema.name.split("/")
        assert schema.data.decode() == ros1_store.generate_msgdef(f"{package}/msg/{name}", ros_version=1)[0]


def test_channel_per_topic_and_callerid_with_metadata(recorded: Path) -> None:
    with open(recorded, "rb") as f:
        summary = make_reader(f).get_summary()
    assert summary is not None
    channels = {(c.topic, c.metadata["callerid"]): c for c in summary.channels.values()}
    assert set(channels) == {
        ("/odom", "/gazebo"), ("/tf", "/gazebo"), ("/ground_truth/odom", "/gazebo"), ("/cmd_vel", "/mover"),
        ("/cmd_vel", "/rosgrade_driver"), ("/rosout", "/mover"),
        ("/rosgrade/stdout", "/mover"), ("/rosgrade/stderr", "/mover"),
    }
    assert channels[("/cmd_vel", "/mover")].metadata == {
        "callerid": "/mover", "md5sum": "9f195f881246fdfa2798d1d3eebca84a", "latching": "0",
    }
    assert channels[("/odom", "/gazebo")].metadata["md5sum"] == "cd5e73d190d741a2f92e81eda573aca7"
    assert channels[("/tf", "/gazebo")].metadata["md5sum"] == "94810edda583a504dfda3829e70d7eec"


def test_log_time_equals_publish_time_and_sequence_counts_per_channel(recorded: Path, run: Run) -> None:
    messages = [r for r in _records(recorded) if isinstance(r, Message)]
    streams = (run.odometry, run.transforms, run.ground_truth, run.commands, run.logs, run.stdout, run.stderr)
    assert len(messages) == sum(map(len, streams))
    per_channel: dict[int, list[int]] = {}
    for m in messages:
        assert m.log_time == m.publish_time
        per_channel.setdefault(m.channel_id, []).append(m.sequence)
    for sequences in per_channel.values():
        assert sequences == list(range(1, len(sequences) + 1))


def test_messages_are_chunked_with_zstd(recorded: Path) -> None:
    with open(recorded, "rb") as f:
        summary = make_reader(f).get_summary()
    assert summary is not None and summary.chunk_indexes
    assert {c.compression for c in summary.chunk_indexes} == {"zstd"}


def test_metadata_records_are_strings_with_json_for_structures(recorded: Path) -> None:
    metadata = {r.name: r.metadata for r in _records(recorded) if isinstance(r, Metadata)}
    assert metadata["rosgrade"]["robot"] == "turtlebot3_waffle"
    assert metadata["rosgrade"]["scenario"] == (
        '{"initial_pose": {"x": -2.0, "y": -0.5, "yaw": 0.0}, "robot": "turtlebot3_waffle"}'
    )
    assert metadata["rosgrade.run"] == {"exit_code": "0", "shutdown_ns": "7000000000", "status": "exited"}


def test_statistics_hold_sim_times_only(recorded: Path, run: Run) -> None:
    (stats,) = [r for r in _records(recorded) if isinstance(r, Statistics)]
    assert stats.message_start_time == run.odometry[0].t_ns
    assert stats.message_end_time == max(s.t_ns for s in run.ground_truth + run.odometry)


def test_same_content_gives_byte_identical_files(tmp_path: Path) -> None:
    a = record(tmp_path / "a.mcap", make_run())
    b = record(tmp_path / "b.mcap", make_run())
    assert a.read_bytes() == b.read_bytes()


def test_different_content_gives_different_files(tmp_path: Path) -> None:
    a = record(tmp_path / "a.mcap", make_run(seed=1))
    b = record(tmp_path / "b.mcap", make_run(seed=2))
    assert a.read_bytes() != b.read_bytes()


def test_small_chunks_still_deterministic_and_readable(tmp_path: Path, run: Run) -> None:
    a = record(tmp_path / "a.mcap", run, chunk_size=2048)
    b = record(tmp_path / "b.mcap", run, chunk_size=2048)
    assert a.read_bytes() == b.read_bytes()
    assert Recording.open(a).odometry().x.tolist() == [s.position[0] for s in run.odometry]


def test_latching_is_recorded(tmp_path: Path) -> None:
    with Recorder(tmp_path / "l.mcap", {}) as rec:
        rec.write("/map_ready", "std_msgs/Bool", b"\x01", 10, "/mapper", latching=True)
    channels = [r for r in _records(tmp_path / "l.mcap") if isinstance(r, Channel)]
    assert channels[0].metadata["latching"] == "1"


def test_add_metadata_after_messages(tmp_path: Path) -> None:
    with Recorder(tmp_path / "m.mcap", METADATA) as rec:
        rec.write("/cmd_vel", "geometry_msgs/Twist", TWIST, 1, "/mover")
        rec.add_metadata("rosgrade.run", {"exit_code": 1, "diagnostics": ["killed"]})
    assert Recording.open(tmp_path / "m.mcap").metadata["rosgrade.run"] == {"exit_code": 1, "diagnostics": ["killed"]}


def test_write_outside_context_is_an_error(tmp_path: Path) -> None:
    rec = Recorder(tmp_path / "x.mcap", {})
    with pytest.raises(RecordingError, match="not open"):
        rec.write("/cmd_vel", "geometry_msgs/Twist", TWIST, 0, "/mover")
    with rec:
        pass
    with pytest.raises(RecordingError, match="closed"):
        rec.add_metadata("rosgrade.run", {})
    with pytest.raises(RecordingError, match="already opened"):
        rec.open()


def test_type_change_on_a_channel_is_an_error(tmp_path: Path) -> None:
    with Recorder(tmp_path / "t.mcap", {}) as rec:
        rec.write("/cmd_vel", "geometry_msgs/Twist", TWIST, 0, "/mover")
        rec.write("/cmd_vel", "geometry_msgs/msg/Twist", TWIST, 1, "/mover")  # same type, other spelling
        with pytest.raises(RecordingError, match="recorded as geometry_msgs/Twist"):
            rec.write("/cmd_vel", "std_msgs/String", b"\0\0\0\0", 2, "/mover")


@pytest.mark.parametrize(
    "args,match",
    [
        (("/cmd_vel", "geometry_msgs/Twist", TWIST, -1, "/mover"), "non-negative integer"),
        (("/cmd_vel", "geometry_msgs/Twist", TWIST, 1.5, "/mover"), "non-negative integer"),
        (("/cmd_vel", "geometry_msgs/Twist", "text", 1, "/mover"), "must be bytes"),
        (("cmd_vel", "geometry_msgs/Twist", TWIST, 1, "/mover"), "not a global name"),
        (("/x", "my_msgs/Unknown", b"", 1, "/mover"), "unknown message type"),
    ],
)
def test_bad_write_is_an_error(tmp_path: Path, args: tuple, match: str) -> None:
    with Recorder(tmp_path / "b.mcap", {}) as rec:
        with pytest.raises(RecordingError, match=match):
            rec.write(*args)


def test_unserializable_metadata_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(RecordingError, match="not JSON-serializable"):
        Recorder(tmp_path / "u.mcap", {"rosgrade": {"robot": object()}})


def test_uncreatable_path_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(RecordingError, match="cannot create recording"):
        Recorder(tmp_path / "missing" / "x.mcap", {}).open()


def test_file_is_complete_after_an_exception_in_the_block(tmp_path: Path) -> None:
    with pytest.raises(ZeroDivisionError), Recorder(tmp_path / "e.mcap", {}) as rec:
        rec.write("/cmd_vel", "geometry_msgs/Twist", TWIST, 5, "/mover")
        1 / 0  # noqa: B018
    recording = Recording.open(tmp_path / "e.mcap", allow_truncated=False)
    assert recording.commands().t.tolist() == [5e-9]


def test_size_cap_drops_and_notes_it(tmp_path: Path) -> None:
    with Recorder(tmp_path / "c.mcap", {}, max_bytes=100) as rec:
        kept = [rec.write("/cmd_vel", "geometry_msgs/Twist", TWIST, i, "/mover") for i in range(4)]
        assert (rec.message_count, rec.payload_bytes, rec.dropped) == (2, 96, 2)
    assert kept == [True, True, False, False]
    recording = Recording.open(tmp_path / "c.mcap")
    assert len(recording.commands()) == 2
    assert recording.metadata["rosgrade.recording"] == {"max_bytes": 100, "dropped": 2}


def test_no_cap_record_when_nothing_dropped(recorded: Path) -> None:
    assert "rosgrade.recording" not in Recording.open(recorded).metadata


def test_header_records_come_first(recorded: Path) -> None:
    assert isinstance(_records(recorded)[0], Header)
