"""Fixtures for the recording tests (helpers live in recording_helpers, importable by name)."""
from __future__ import annotations

from pathlib import Path

import pytest
from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from rosbags.typesys.store import Typestore

from recording_helpers import MessageBuilder, Run, make_run, record


@pytest.fixture(scope="session")
def run() -> Run:
    return make_run()


@pytest.fixture(scope="session")
def recorded(tmp_path_factory: pytest.TempPathFactory, run: Run) -> Path:
    return record(tmp_path_factory.mktemp("rec") / "run.mcap", run)


@pytest.fixture(scope="session")
def ros1_store() -> Typestore:
    """An independent rosbags Noetic store (with tf2_msgs), the reference the tests compare against."""
    store = get_typestore(Stores.ROS1_NOETIC)
    store.register(get_types_from_msg("geometry_msgs/TransformStamped[] transforms", "tf2_msgs/msg/TFMessage"))
    return store


@pytest.fixture(scope="session")
def ros2_store() -> Typestore:
    return get_typestore(Stores.ROS2_HUMBLE)


@pytest.fixture(scope="session")
def ros1_msgs(ros1_store: Typestore) -> MessageBuilder:
    return MessageBuilder(ros1_store, ros1=True)


@pytest.fixture(scope="session")
def ros2_msgs(ros2_store: Typestore) -> MessageBuilder:
    return MessageBuilder(ros2_store, ros1=False)
