"""ROS 2 recordings: the recorder writes ros2msg/cdr MCAP that rosbags' rosbag2 reader opens, and rosgrade's reader
turns it into the same series as a ROS 1 recording of the same run (commands as TwistStamped, /rosout levels)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from rosbags.highlevel import AnyReader

from recording_helpers import Run
from grader.recording import Recorder, Recording
from grader.recording import serialize_cdr as cdr
from grader.recording.ros2_messages import ros2_catalog

CATALOG = ros2_catalog()


def _twist_stamped(t_ns: int, linear: tuple, angular: tuple) -> bytes:
    t = CATALOG.message_class
    stamp = t("builtin_interfaces/msg/Time")(sec=t_ns // 10**9, nanosec=t_ns % 10**9)
    vector = t("geometry_msgs/msg/Vector3")
    msg = t("geometry_msgs/msg/TwistStamped")(
        header=t("std_msgs/msg/Header")(stamp=stamp, frame_id=""),
        twist=t("geometry_msgs/msg/Twist")(linear=vector(*linear), angular=vector(*angular)))
    return CATALOG.encode("geometry_msgs/msg/TwistStamped", msg)


@pytest.fixture(scope="module")
def ros2_file(tmp_path_factory: pytest.TempPathFactory, run: Run) -> Path:
    path = tmp_path_factory.mktemp("ros2") / "run.mcap"
    metadata = {"rosgrade": {"odometry_topic": "/odom", "command_topics": ["/cmd_vel"],
                             "command_types": ["geometry_msgs/msg/TwistStamped"], "client_library": "rclpy"}}
    with Recorder(path, metadata=metadata, catalog=CATALOG) as rec:
        for sample in run.odometry:
            rec.write("/odom", "nav_msgs/msg/Odometry", cdr.odometry_cdr(sample, 0), sample.t_ns, "/gazebo",
                      origin="world")
        for c in run.commands:
            rec.write("/cmd_vel", "geometry_msgs/msg/TwistStamped", _twist_stamped(c.t_ns, c.linear, c.angular),
                      c.t_ns, "/move_circle", origin="node")
        rec.write("/rosout", "rcl_interfaces/msg/Log",
                  cdr.log_cdr(3_000_000_000, 30, "move_circle", "careful", "move_circle.py", "tick", 9),
                  3_000_000_000, "/move_circle", origin="node")
        rec.write("/rosgrade/stdout", "std_msgs/msg/String", cdr.string_cdr("hello"), 3_500_000_000, "/move_circle",
                  origin="node")
    return path


def test_rosbags_reads_it_as_a_rosbag2_mcap(ros2_file: Path, run: Run) -> None:
    with AnyReader([ros2_file]) as reader:
        assert reader.is2
        types = {c.topic: c.msgtype for c in reader.connections}
        odometry = [reader.deserialize(data, c.msgtype) for c, _, data in reader.messages() if c.topic == "/odom"]
    assert types["/cmd_vel"] == "geometry_msgs/msg/TwistStamped" and types["/rosout"] == "rcl_interfaces/msg/Log"
    assert [m.pose.pose.position.x for m in odometry] == [s.position[0] for s in run.odometry]


def test_reader_gives_the_ros1_series(ros2_file: Path, recorded: Path) -> None:
    ours, ros1 = Recording.open(ros2_file), Recording.open(recorded)
    assert ours.format == "mcap-ros2" and ours.truncated is None
    a, b = ours.odometry(), ros1.odometry()
    for name in ("t", "x", "y", "yaw", "vx", "wz"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def test_commands_read_from_twist_stamped(ros2_file: Path, run: Run) -> None:
    commands = Recording.open(ros2_file).commands()
    assert len(commands.t) == len(run.commands)
    in_time_order = sorted(run.commands, key=lambda c: c.t_ns)  # the reader orders messages by log time
    np.testing.assert_array_equal(commands.linear, np.array([c.linear for c in in_time_order]))
    assert set(commands.origin) == {"node"}


def test_rosout_levels_on_the_ros1_scale(ros2_file: Path) -> None:
    [line] = Recording.open(ros2_file).rosout()
    assert (line.level, line.name, line.msg, line.file, line.function, line.line) == (
        4, "move_circle", "careful", "move_circle.py", "tick", 9)


def test_output_lines_include_ros2_log_and_print(ros2_file: Path) -> None:
    lines = Recording.open(ros2_file).output_lines()
    assert [(line.stream, line.text) for line in lines] == [("rosout", "careful"), ("stdout", "hello")]


def test_channels_keep_who_published(ros2_file: Path) -> None:
    topics = {(t.topic, t.origin, t.callerid) for t in Recording.open(ros2_file).topics()}
    assert ("/odom", "world", "/gazebo") in topics and ("/cmd_vel", "node", "/move_circle") in topics
