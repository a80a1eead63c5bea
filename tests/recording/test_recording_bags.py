"""ROS 1 bags and ROS 2 bags (sqlite3 folder, .db3, MCAP) read into the same arrays as our MCAP."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from rosbags.rosbag1 import Writer as Bag1Writer
from rosbags.rosbag2 import StoragePlugin
from rosbags.rosbag2 import Writer as Bag2Writer

from grader.recording import Recording
from recording_helpers import MessageBuilder, Run


def _messages(run: Run, msgs: MessageBuilder, *, ground_truth: bool = True) -> list[tuple[str, str, str, int, object]]:
    """(topic, type, callerid, t_ns, message) for a run, in time order."""
    out = [
        ("/odom", "nav_msgs/msg/Odometry", "/gazebo", s.t_ns, msgs.from_odometry_sample(s, i))
        for i, s in enumerate(run.odometry)
    ]
    out += [
        ("/tf", "tf2_msgs/msg/TFMessage", "/gazebo", s.t_ns, msgs.from_transform_sample(s, i))
        for i, s in enumerate(run.transforms)
    ]
    if ground_truth:
        out += [
            ("/ground_truth/odom", "nav_msgs/msg/Odometry", "/gazebo", s.t_ns, msgs.from_ground_truth_sample(s, i))
            for i, s in enumerate(run.ground_truth)
        ]
    out += [
        ("/cmd_vel", "geometry_msgs/msg/Twist", c.callerid, c.t_ns, msgs.twist(c.linear, c.angular))
        for c in run.commands
    ]
    return sorted(out, key=lambda m: m[3])


def write_bag1(path: Path, run: Run, msgs: MessageBuilder, *, ground_truth: bool = True) -> Path:
    with Bag1Writer(path) as writer:
        connections = {}
        for topic, msgtype, callerid, t_ns, msg in _messages(run, msgs, ground_truth=ground_truth):
            key = (topic, callerid)
            if key not in connections:
                connections[key] = writer.add_connection(topic, msgtype, typestore=msgs.store, callerid=callerid)
            writer.write(connections[key], t_ns, msgs.serialize(msg))
    return path


def write_bag2(path: Path, run: Run, msgs: MessageBuilder, plugin: StoragePlugin) -> Path:
    with Bag2Writer(path, version=9, storage_plugin=plugin) as writer:
        connections = {}
        for topic, msgtype, _, t_ns, msg in _messages(run, msgs):
            if topic not in connections:
                connections[topic] = writer.add_connection(topic, msgtype, typestore=msgs.store)
            writer.write(connections[topic], t_ns, msgs.serialize(msg))
    return path


@pytest.fixture(scope="module")
def ours(recorded: Path) -> Recording:
    return Recording.open(recorded)


@pytest.fixture(scope="module")
def bag1(tmp_path_factory: pytest.TempPathFactory, run: Run, ros1_msgs: MessageBuilder) -> Recording:
    return Recording.open(write_bag1(tmp_path_factory.mktemp("bag1") / "run.bag", run, ros1_msgs))


@pytest.fixture(scope="module")
def bag2_dirs(tmp_path_factory: pytest.TempPathFactory, run: Run, ros2_msgs: MessageBuilder) -> dict[str, Path]:
    base = tmp_path_factory.mktemp("bag2")
    return {
        "sqlite3": write_bag2(base / "sqlite", run, ros2_msgs, StoragePlugin.SQLITE3),
        "mcap": write_bag2(base / "mcap", run, ros2_msgs, StoragePlugin.MCAP),
    }


def _ros2_paths(dirs: dict[str, Path]) -> dict[str, Path]:
    return {
        "folder-sqlite3": dirs["sqlite3"],
        "db3-file": next(dirs["sqlite3"].glob("*.db3")),
        "folder-mcap": dirs["mcap"],
        "mcap-file": next(dirs["mcap"].glob("*.mcap")),
    }


@pytest.fixture(scope="module", params=["folder-sqlite3", "db3-file", "folder-mcap", "mcap-file"])
def bag2(request: pytest.FixtureRequest, bag2_dirs: dict[str, Path]) -> Recording:
    return Recording.open(_ros2_paths(bag2_dirs)[request.param])


def _same_series(a: object, b: object) -> None:
    for name in ("t", "x", "y", "yaw", "vx", "wz"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def test_bag1_format_and_callerids(bag1: Recording) -> None:
    assert bag1.format == "rosbag1" and bag1.truncated is None and bag1.metadata == {}
    assert {(t.topic, t.callerid) for t in bag1.topics()} >= {("/cmd_vel", "/mover"), ("/cmd_vel", "/rosgrade_driver")}


def test_bag1_odometry_equals_ours(bag1: Recording, ours: Recording) -> None:
    _same_series(bag1.odometry(), ours.odometry())


def test_bag1_ground_truth_equals_ours(bag1: Recording, ours: Recording) -> None:
    _same_series(bag1.ground_truth(), ours.ground_truth())


def test_bag1_commands_equal_ours(bag1: Recording, ours: Recording) -> None:
    a, b = bag1.commands(), ours.commands()
    for name in ("t", "linear", "angular", "topic", "callerid"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def test_bag1_transforms_equal_ours(bag1: Recording, ours: Recording) -> None:
    a, b = bag1.transforms(), ours.transforms()
    for name in ("t", "frame_id", "child_frame_id", "translation", "rotation"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def test_bag1_without_ground_truth(tmp_path: Path, run: Run, ros1_msgs: MessageBuilder) -> None:
    recording = Recording.open(write_bag1(tmp_path / "real_robot.bag", run, ros1_msgs, ground_truth=False))
    assert recording.ground_truth() is None
    assert len(recording.odometry()) == len(run.odometry)


def test_bag2_format(bag2: Recording) -> None:
    # a lone .mcap is read as MCAP (streaming, keeps channel metadata); a bag folder or .db3 through rosbags
    assert bag2.format in ("rosbag2", "mcap-ros2") and bag2.truncated is None
    assert (bag2.format == "mcap-ros2") == (bag2.path.suffix == ".mcap")
    assert ("/odom", "nav_msgs/Odometry", "") in {(t.topic, t.type, t.callerid) for t in bag2.topics()}


def test_bag2_odometry_and_ground_truth_equal_ours(bag2: Recording, ours: Recording) -> None:
    _same_series(bag2.odometry(), ours.odometry())
    _same_series(bag2.ground_truth(), ours.ground_truth())


def test_bag2_commands_equal_ours_without_callerid(bag2: Recording, ours: Recording) -> None:
    a, b = bag2.commands(), ours.commands()
    np.testing.assert_array_equal(a.t, b.t)
    np.testing.assert_array_equal(a.linear, b.linear)
    np.testing.assert_array_equal(a.angular, b.angular)
    assert set(a.callerid) == {""}


def test_bag2_transforms_equal_ours(bag2: Recording, ours: Recording) -> None:
    np.testing.assert_array_equal(bag2.transforms().translation, ours.transforms().translation)
    np.testing.assert_array_equal(bag2.transforms().t, ours.transforms().t)
