"""MessageCatalog: schema text and md5s as rosbags/genpy give them; strict decoding of untrusted bytes."""
from __future__ import annotations

import struct

import pytest
from rosbags.typesys.store import Typestore

from grader.recording import MessageCatalog, RecordingError, default_catalog

KNOWN_MD5 = {
    "geometry_msgs/Twist": "9f195f881246fdfa2798d1d3eebca84a",
    "nav_msgs/Odometry": "cd5e73d190d741a2f92e81eda573aca7",
    "tf2_msgs/TFMessage": "94810edda583a504dfda3829e70d7eec",
    "std_msgs/String": "992ce8a1687cec8c8bd883ec73ca41d1",
    "rosgraph_msgs/Log": "acffd30cd6b6de30f120938c17c593fb",
    "rosgraph_msgs/Clock": "a9c97c1d230cfc112e270351a944ee47",
}
USED_TYPES = [
    "std_msgs/String", "std_msgs/Float64", "std_msgs/Int32", "std_msgs/Bool", "std_msgs/Header", "std_msgs/Empty",
    "geometry_msgs/Twist", "geometry_msgs/TwistStamped", "geometry_msgs/Pose", "geometry_msgs/PoseStamped",
    "geometry_msgs/Point", "geometry_msgs/Quaternion", "geometry_msgs/Vector3", "geometry_msgs/TransformStamped",
    "nav_msgs/Odometry", "nav_msgs/Path", "sensor_msgs/Imu", "sensor_msgs/LaserScan", "sensor_msgs/JointState",
    "tf2_msgs/TFMessage", "rosgraph_msgs/Log", "rosgraph_msgs/Clock",
]


@pytest.fixture(scope="module")
def catalog() -> MessageCatalog:
    return default_catalog()


@pytest.mark.parametrize("type_name,md5", KNOWN_MD5.items())
def test_md5_equals_known_value(catalog: MessageCatalog, type_name: str, md5: str) -> None:
    assert catalog.md5sum(type_name) == md5


@pytest.mark.parametrize("type_name", USED_TYPES)
def test_definition_equals_rosbags_generate_msgdef(
    catalog: MessageCatalog, ros1_store: Typestore, type_name: str
) -> None:
    package, name = type_name.split("/")
    text, md5 = ros1_store.generate_msgdef(f"{package}/msg/{name}", ros_version=1)
    assert catalog.definition(type_name) == text
    assert catalog.md5sum(type_name) == md5


def test_definition_is_concatenated_with_msg_separators(catalog: MessageCatalog) -> None:
    text = catalog.definition("nav_msgs/Odometry")
    assert text.startswith("std_msgs/Header header\nstring child_frame_id\n")
    assert f"{'=' * 80}\nMSG: geometry_msgs/PoseWithCovariance\n" in text
    assert "MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n" in text


def test_both_type_spellings_are_accepted(catalog: MessageCatalog) -> None:
    assert catalog.md5sum("geometry_msgs/msg/Twist") == catalog.md5sum("geometry_msgs/Twist")
    assert catalog.known("geometry_msgs/msg/Twist") and catalog.known("geometry_msgs/Twist")


@pytest.mark.parametrize("bad", ["Twist", "geometry_msgs/Twist/x", "", "geometry_msgs/srv/Twist", "../etc/passwd"])
def test_malformed_type_name_is_an_error(catalog: MessageCatalog, bad: str) -> None:
    assert not catalog.known(bad)
    with pytest.raises(RecordingError, match="not a ROS message type name"):
        catalog.md5sum(bad)


def test_unknown_type_is_an_error(catalog: MessageCatalog) -> None:
    assert not catalog.known("my_msgs/Secret")
    with pytest.raises(RecordingError, match="unknown message type 'my_msgs/Secret'"):
        catalog.decode("my_msgs/Secret", b"")


def test_ros2_internal_types_are_hidden(catalog: MessageCatalog) -> None:
    assert not catalog.known("builtin_interfaces/Time")
    assert "builtin_interfaces/Time" not in catalog.types()
    assert set(USED_TYPES) <= set(catalog.types())


def test_decode_round_trips_a_twist(catalog: MessageCatalog) -> None:
    data = struct.pack("<6d", 0.5, 0.0, 0.0, 0.0, 0.0, -1.25)
    msg = catalog.decode("geometry_msgs/Twist", data)
    assert (msg.linear.x, msg.angular.z) == (0.5, -1.25)  # type: ignore[attr-defined]
    assert catalog.encode("geometry_msgs/Twist", msg) == data


@pytest.mark.parametrize("size", [0, 1, 47, 49, 96])
def test_decode_rejects_wrong_length_twist(catalog: MessageCatalog, size: int) -> None:
    with pytest.raises(RecordingError, match=rf"^{size} bytes are not a valid geometry_msgs/Twist message: "):
        catalog.decode("geometry_msgs/Twist", bytes(size))


def test_decode_rejects_trailing_bytes(catalog: MessageCatalog) -> None:
    with pytest.raises(RecordingError, match="trailing bytes"):
        catalog.decode("std_msgs/String", struct.pack("<I", 2) + b"hi" + b"\0")


def test_decode_rejects_too_short(catalog: MessageCatalog) -> None:
    with pytest.raises(RecordingError, match="too short"):
        catalog.decode("std_msgs/Float64", bytes(7))


def test_decode_rejects_string_length_beyond_data(catalog: MessageCatalog) -> None:
    with pytest.raises(RecordingError, match="not a valid std_msgs/String"):
        catalog.decode("std_msgs/String", struct.pack("<I", 0xFFFFFFFF) + b"abc")


def test_decode_rejects_invalid_utf8(catalog: MessageCatalog) -> None:
    with pytest.raises(RecordingError, match="utf-8"):
        catalog.decode("std_msgs/String", struct.pack("<I", 2) + b"\xff\xfe")


def test_decode_rejects_huge_array_count(catalog: MessageCatalog) -> None:
    # JointState: header, then string[] name with a count far beyond the data
    data = struct.pack("<III", 0, 0, 0) + struct.pack("<I", 0) + struct.pack("<I", 0x7FFFFFFF)
    with pytest.raises(RecordingError, match="not a valid sensor_msgs/JointState"):
        catalog.decode("sensor_msgs/JointState", data)


def test_decode_accepts_memoryview(catalog: MessageCatalog) -> None:
    msg = catalog.decode("std_msgs/Float64", memoryview(struct.pack("<d", 2.5)))
    assert msg.data == 2.5  # type: ignore[attr-defined]


def test_definitions_are_cached(catalog: MessageCatalog) -> None:
    assert catalog.definition("sensor_msgs/Imu") is catalog.definition("sensor_msgs/Imu")


@pytest.mark.parametrize(
    "service,md5",
    [
        ("std_srvs/Empty", "d41d8cd98f00b204e9800998ecf8427e"),
        ("std_srvs/Trigger", "937c9679a518e3a18d831e57125ea522"),
        ("std_srvs/SetBool", "09fb03525b03e7ea1fd3992bafd87e16"),
    ],
)
def test_std_srvs_md5(catalog: MessageCatalog, service: str, md5: str) -> None:
    assert catalog.service_md5sum(service) == md5


def test_std_srvs_request_and_response_decode(catalog: MessageCatalog) -> None:
    response = catalog.decode("std_srvs/TriggerResponse", b"\x01" + struct.pack("<I", 2) + b"ok")
    assert (response.success, response.message) == (True, "ok")  # type: ignore[attr-defined]
    assert catalog.decode("std_srvs/SetBoolRequest", b"\x00").data is False  # type: ignore[attr-defined]
