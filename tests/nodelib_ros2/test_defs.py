"""The checked-in ROS 2 definition table is what the generator makes from rosbags now, and covers what nodes use."""
from __future__ import annotations

import pytest

from . import gen_defs
from .helpers import covered_types


def test_checked_in_table_equals_generator_output():
    assert gen_defs.TARGET.read_text() == gen_defs.render(), "run: python -m tests.nodelib_ros2.gen_defs"


@pytest.mark.parametrize("type_name", [
    "geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped", "nav_msgs/msg/Odometry", "rcl_interfaces/msg/Log",
    "rosgraph_msgs/msg/Clock", "tf2_msgs/msg/TFMessage", "sensor_msgs/msg/LaserScan", "sensor_msgs/msg/Imu",
    "std_msgs/msg/Empty", "builtin_interfaces/msg/Time", "std_srvs/srv/SetBool_Request"])
def test_table_holds(type_name):
    assert type_name in covered_types()


def test_hashes_are_rosbags_rihs01():
    store = gen_defs.typestore()
    messages, services = gen_defs.table(store)
    assert messages["geometry_msgs/msg/Twist"][2] == store.hash_rihs01("geometry_msgs/msg/Twist")
    assert messages["geometry_msgs/msg/Twist"][2] == (
        "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a")
    assert set(services) == {"std_srvs/srv/Empty", "std_srvs/srv/SetBool", "std_srvs/srv/Trigger",
                             "example_interfaces/srv/AddTwoInts", *(f"rcl_interfaces/srv/{name}" for name in (
                                 "DescribeParameters", "GetParameterTypes", "GetParameters", "ListParameters",
                                 "SetParameters", "SetParametersAtomically"))}
    assert all(h.startswith("RIHS01_") and len(h) == 71 for h in services.values())


def test_defaults_rosbags_drops_are_restored():
    messages, _ = gen_defs.table(gen_defs.typestore())
    fields = {f[0]: f[5] for f in messages["geometry_msgs/msg/Quaternion"][0]}
    assert fields == {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}
