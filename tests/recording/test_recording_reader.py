"""Recording: our MCAP read back into the arrays the metrics use."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from grader.recording import (
    CommandSeries,
    LogLine,
    OutputLine,
    Recorder,
    Recording,
    RecordingError,
    TimeSeries,
    TopicInfo,
    odometry_bytes,
    twist_bytes,
)
from grader.recording.series import yaw_from_quaternion
from recording_helpers import METADATA, Run


@pytest.fixture(scope="module")
def recording(recorded: Path) -> Recording:
    return Recording.open(recorded)


def test_format_and_not_truncated(recording: Recording) -> None:
    assert recording.format == "mcap-ros1"
    assert recording.truncated is None


def test_odometry_arrays_exact(recording: Recording, run: Run) -> None:
    odom = recording.odometry()
    assert isinstance(odom, TimeSeries) and odom.topic == "/odom" and len(odom) == len(run.odometry)
    assert odom.t.dtype == np.float64
    assert odom.t.tolist() == [s.t_ns / 1e9 for s in run.odometry]
    assert odom.x.tolist() == [s.position[0] for s in run.odometry]
    assert odom.y.tolist() == [s.position[1] for s in run.odometry]
    assert odom.vx.tolist() == [s.linear[0] for s in run.odometry]
    assert odom.wz.tolist() == [s.angular[2] for s in run.odometry]


def test_yaw_matches_quaternion_and_stays_in_range(recording: Recording, run: Run) -> None:
    yaw = recording.odometry().yaw
    angles = [2 * math.atan2(s.orientation[2], s.orientation[3]) for s in run.odometry]
    expected = [math.atan2(math.sin(a), math.cos(a)) for a in angles]
    np.testing.assert_allclose(yaw, expected, atol=1e-12)
    assert np.all(yaw > -math.pi) and np.all(yaw <= math.pi)


def test_yaw_of_half_turn_is_plus_pi() -> None:
    yaw = yaw_from_quaternion(*(np.array([v]) for v in (0.0, 0.0, 1.0, 0.0)))
    assert yaw.tolist() == [math.pi]
    assert yaw_from_quaternion(*(np.array([v]) for v in (0.0, 0.0, -1.0, 0.0))).tolist() == [math.pi]


def test_ground_truth_arrays_exact(recording: Recording, run: Run) -> None:
    truth = recording.ground_truth()
    assert truth is not None and truth.topic == "/ground_truth/odom"
    assert truth.t.tolist() == [s.t_ns / 1e9 for s in run.ground_truth]
    assert truth.x.tolist() == [s.position[0] for s in run.ground_truth]
    assert truth.y.tolist() == [s.position[1] for s in run.ground_truth]
    assert truth.vx.tolist() == [s.linear[0] for s in run.ground_truth]
    assert truth.wz.tolist() == [s.angular[2] for s in run.ground_truth]


def test_commands_with_callerid_in_time_order(recording: Recording, run: Run) -> None:
    cmds = recording.commands()
    expected = sorted(run.commands, key=lambda c: c.t_ns)
    assert isinstance(cmds, CommandSeries) and len(cmds) == len(expected)
    assert cmds.t.tolist() == [c.t_ns / 1e9 for c in expected]
    assert cmds.linear.tolist() == [list(c.linear) for c in expected]
    assert cmds.angular.tolist() == [list(c.angular) for c in expected]
    assert cmds.callerid.tolist() == [c.callerid for c in expected]
    assert cmds.topic.tolist() == ["/cmd_vel"] * len(expected)
    assert cmds.vx.tolist() == [c.linear[0] for c in expected] and cmds.wz.tolist() == [c.angular[2] for c in expected]


def test_commands_on_missing_topic_are_empty(recording: Recording) -> None:
    cmds = recording.commands("/nope")
    assert len(cmds) == 0 and cmds.linear.shape == (0, 3)


def test_transforms(recording: Recording, run: Run) -> None:
    tf = recording.transforms()
    assert tf.t.tolist() == [s.t_ns / 1e9 for s in run.transforms]
    assert set(tf.frame_id) == {"odom"} and set(tf.child_frame_id) == {"base_footprint"}
    assert tf.translation.tolist() == [list(s.translation) for s in run.transforms]
    assert tf.rotation.tolist() == [list(s.rotation) for s in run.transforms]


def test_output_lines_merge_streams_in_time_order(recording: Recording, run: Run) -> None:
    expected = sorted(
        [(t, "stdout", text) for t, text in run.stdout]
        + [(t, "stderr", text) for t, text in run.stderr]
        + [(line.t_ns, "rosout", line.msg) for line in run.logs]
    )
    lines = recording.output_lines()
    assert all(isinstance(line, OutputLine) for line in lines)
    assert lines == [OutputLine(t / 1e9, stream, text) for t, stream, text in expected]
    assert [(t, stream, text) for t, stream, text in lines] == lines  # unpacks as the documented 3-tuple


def test_rosout_carries_level_and_origin(recording: Recording, run: Run) -> None:
    assert recording.rosout() == [
        LogLine(line.t_ns / 1e9, line.level, "/mover", line.msg, "mover.py", "main", 12) for line in run.logs
    ]


def test_topics_summary(recording: Recording, run: Run) -> None:
    topics = recording.topics()
    assert TopicInfo("/odom", "nav_msgs/Odometry", "/gazebo", len(run.odometry)) in topics
    assert TopicInfo("/cmd_vel", "geometry_msgs/Twist", "/rosgrade_driver", 1) in topics
    assert TopicInfo("/rosout", "rosgraph_msgs/Log", "/mover", len(run.logs)) in topics
    assert topics == sorted(topics)


def test_metadata_json_values_are_decoded(recording: Recording) -> None:
    assert recording.metadata["rosgrade"]["scenario"] == METADATA["rosgrade"]["scenario"]
    assert recording.metadata["rosgrade"]["rosgrade_version"] == "0.1.0"
    assert recording.metadata["rosgrade.run"]["exit_code"] == 0


def test_generic_messages_iterator(recording: Recording, run: Run) -> None:
    got = list(recording.messages("/rosgrade/stdout"))
    assert [(t, m.data) for t, m in got] == run.stdout  # type: ignore[attr-defined]
    assert [t for t, _ in recording.messages("/cmd_vel", callerid="/rosgrade_driver")] == [run.commands[-1].t_ns]
    assert list(recording.messages("/nope")) == []


def test_odometry_topic_from_metadata(tmp_path: Path, run: Run) -> None:
    path = tmp_path / "husky.mcap"
    with Recorder(path, {"rosgrade": {"robot": "husky", "odometry_topic": "/husky_velocity_controller/odom"}}) as rec:
        for seq, s in enumerate(run.odometry[:3]):
            rec.write("/husky_velocity_controller/odom", "nav_msgs/Odometry", odometry_bytes(s, seq), s.t_ns, "/gazebo")
            rec.write("/odom", "nav_msgs/Odometry", odometry_bytes(s, seq), s.t_ns, "/student")
    assert Recording.open(path).odometry().topic == "/husky_velocity_controller/odom"


@pytest.mark.parametrize(
    "topics,expected",
    [
        ({"/a_student_odom": "/student", "/wheel/odom": "/gazebo"}, "/wheel/odom"),
        ({"/odom": "/student", "/husky_velocity_controller/odom": "/gazebo"}, "/husky_velocity_controller/odom"),
        ({"/odom": "/gazebo", "/a/odom": "/gazebo"}, "/odom"),
        ({"/odom": "/turtlebot3_core", "/a/odom": "/other"}, "/odom"),  # a real robot's bag
        ({"/b/odom": "/x", "/a/odom": "/y"}, "/a/odom"),
    ],
)
def test_odometry_topic_without_metadata(tmp_path: Path, run: Run, topics: dict[str, str], expected: str) -> None:
    path = tmp_path / "sim.mcap"
    with Recorder(path, {}) as rec:
        for seq, s in enumerate(run.odometry[:3]):
            for topic, callerid in topics.items():
                rec.write(topic, "nav_msgs/Odometry", odometry_bytes(s, seq), s.t_ns, callerid)
    recording = Recording.open(path)
    assert recording.odometry_topic() == expected
    assert recording.ground_truth() is None


def test_command_topics_from_metadata(tmp_path: Path) -> None:
    path = tmp_path / "cmd.mcap"
    with Recorder(path, {"rosgrade": {"command_topics": ["/cmd_vel"]}}) as rec:
        rec.write("/cmd_vel", "geometry_msgs/Twist", twist_bytes((1.0, 0.0, 0.0), (0.0, 0.0, 0.0)), 1, "/a")
        rec.write("/turtle1/cmd_vel", "geometry_msgs/Twist", twist_bytes((2.0, 0.0, 0.0), (0.0, 0.0, 0.0)), 2, "/a")
    recording = Recording.open(path)
    assert recording.commands().vx.tolist() == [1.0]
    assert recording.commands("/turtle1/cmd_vel").vx.tolist() == [2.0]


def test_no_odometry_is_a_clear_error(tmp_path: Path) -> None:
    path = tmp_path / "empty.mcap"
    with Recorder(path, {}):
        pass
    recording = Recording.open(path)
    with pytest.raises(RecordingError, match="has no nav_msgs/Odometry topic"):
        recording.odometry()
    with pytest.raises(RecordingError, match="no nav_msgs/Odometry messages on /odom"):
        recording.odometry("/odom")
    assert recording.topics() == [] and recording.output_lines() == [] and len(recording.transforms()) == 0


def test_bad_payload_in_a_file_is_a_recording_error(tmp_path: Path) -> None:
    path = tmp_path / "bad.mcap"
    with Recorder(path, {}) as rec:  # the recorder trusts its caller; the reader does not trust the file
        rec.write("/odom", "nav_msgs/Odometry", b"\0" * 20, 1, "/gazebo")
        rec.write("/chatter", "std_msgs/String", b"\x09\0\0\0abc", 1, "/talker")
    recording = Recording.open(path)
    with pytest.raises(RecordingError, match="not a nav_msgs/Odometry message"):
        recording.odometry()
    with pytest.raises(RecordingError, match="a message on /chatter does not decode as std_msgs/String"):
        list(recording.messages("/chatter"))
