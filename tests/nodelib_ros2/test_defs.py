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
    messages, services, _ = gen_defs.table(store)
    assert messages["geometry_msgs/msg/Twist"][2] == store.hash_rihs01("geometry_msgs/msg/Twist")
    assert messages["geometry_msgs/msg/Twist"][2] == (
        "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a")
    assert set(services) == {"std_srvs/srv/Empty", "std_srvs/srv/SetBool", "std_srvs/srv/Trigger",
                             "example_interfaces/srv/AddTwoInts", "action_msgs/srv/CancelGoal",
                             "example_interfaces/action/Fibonacci_SendGoal",
                             "example_interfaces/action/Fibonacci_GetResult", *(f"rcl_interfaces/srv/{name}" for name in (
                                 "DescribeParameters", "GetParameterTypes", "GetParameters", "ListParameters",
                                 "SetParameters", "SetParametersAtomically")),
                             *(f"turtlesim/srv/{name}" for name in (
                                 "Kill", "SetPen", "Spawn", "TeleportAbsolute", "TeleportRelative")),
                             "turtlesim/action/RotateAbsolute_SendGoal", "turtlesim/action/RotateAbsolute_GetResult"}
    assert all(h.startswith("RIHS01_") and len(h) == 71 for h in services.values())


def test_defaults_rosbags_drops_are_restored():
    messages, _, _ = gen_defs.table(gen_defs.typestore())
    fields = {f[0]: f[5] for f in messages["geometry_msgs/msg/Quaternion"][0]}
    assert fields == {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}


def test_action_types_hash_as_the_jazzy_wheels_describe_them():
    """RIHS01 of share/*/CancelGoal.json, GoalStatusArray.json (ros-jazzy-action-msgs) and of test_msgs' Fibonacci,
    whose definition example_interfaces' repeats (so its derived types are checked under that name)."""
    from rosbags.typesys import get_types_from_msg

    from grader.interfaces.derived import action_types
    from grader.recording.ros2_messages import Ros2Catalog
    messages, services, actions = gen_defs.table(gen_defs.typestore())
    assert services["action_msgs/srv/CancelGoal"] == (
        "RIHS01_573d8b0a534451d7bc2ac8c5ffde8ac14b8593b7001175d0cd6516dcbeb8689a")
    assert messages["action_msgs/msg/GoalStatusArray"][2] == (
        "RIHS01_6c1684b00f177d37438febe6e709fc4e2b0d4248dca4854946f9ed8b30cda83e")
    assert set(actions) == {"example_interfaces/action/Fibonacci", "turtlesim/action/RotateAbsolute"}
    parts = [next(iter(get_types_from_msg(text, "pkg/msg/Part").values()))
             for text in ("int32 order", "int32[] sequence", "int32[] sequence")]
    catalog = Ros2Catalog(action_types("test_msgs/action/Fibonacci", *parts))
    assert catalog.md5sum("test_msgs/action/Fibonacci") == (
        "RIHS01_be9273e3557225044b4a040811112491f7079326e3a573f83258b0b4c30bd069")
