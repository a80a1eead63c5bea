"""Message classes: the genpy behaviours listed in the reference (section e, behaviours 11-12), checked by name."""
from __future__ import annotations

import io
import time

import numpy as np
import pytest

import genpy
import geometry_msgs.msg
from genpy.message import SerializationError
from geometry_msgs.msg import Quaternion, Twist, Vector3
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64, String


def _bytes(msg) -> bytes:
    buff = io.BytesIO()
    msg.serialize(buff)
    return buff.getvalue()


def test_positional_and_keyword_constructors():
    assert Twist(Vector3(1, 2, 3), Vector3(4, 5, 6)).angular.z == 6
    assert Twist(linear=Vector3(x=1)).linear.x == 1


def test_constructor_error_texts():
    with pytest.raises(TypeError, match=r"^Invalid number of arguments, args should be \['linear', 'angular'\] "
                                        r"args are\(x: 1\ny: 0\nz: 0,\)$"):
        Twist(Vector3(1, 0, 0))
    with pytest.raises(TypeError, match="^Message constructor may only use args OR keywords, not both$"):
        Twist(Vector3(), linear=Vector3())
    with pytest.raises(AttributeError, match="^foo is not an attribute of Twist$"):
        Twist(foo=1)
    with pytest.raises(TypeError, match=r"args should be \['x', 'y', 'z'\] args are\(1, 2\)$"):
        Vector3(1, 2)


def test_defaults_and_no_coercion():
    odom = Odometry()
    assert odom.pose.covariance == [0.0] * 36 and odom.header.stamp == genpy.Time(0)
    assert repr(odom.header.stamp) == "genpy.Time[0]"
    assert (Quaternion().x, Quaternion().w) == (0.0, 0.0)
    assert type(Float64(3).data) is int
    assert str(Vector3(1, 2, 3)).startswith("x: 1\n")


def test_slots_metadata_equality_and_hash():
    t = Twist()
    with pytest.raises(AttributeError, match="'Twist' object has no attribute 'foo'"):
        t.foo = 1
    t.linear = 5  # accepted; fails only when serialized
    assert Twist.__slots__ == ["linear", "angular"]
    assert Twist._slot_types == ["geometry_msgs/Vector3", "geometry_msgs/Vector3"]
    assert Twist() == Twist() and Vector3(1, 0, 0) == Vector3(1.0, 0, 0) and Twist() != 0
    with pytest.raises(TypeError, match="unhashable type: 'Twist'"):
        hash(Twist())


def test_md5sums_and_types():
    assert (Twist._type, Twist._md5sum) == ("geometry_msgs/Twist", "9f195f881246fdfa2798d1d3eebca84a")
    assert (Odometry._md5sum, Odometry._has_header) == ("cd5e73d190d741a2f92e81eda573aca7", True)
    assert String._md5sum == "992ce8a1687cec8c8bd883ec73ca41d1"
    assert Vector3._md5sum == "4a842b65f413084dc2b10fb484ea7f17"
    from tf2_msgs.msg import TFMessage
    assert TFMessage._md5sum == "94810edda583a504dfda3829e70d7eec"


def test_full_text_equals_rosbags_definition():
    rosbags = pytest.importorskip("rosbags.typesys")
    store = rosbags.get_typestore(rosbags.Stores.ROS1_NOETIC)
    for cls in (Twist, Odometry, String, __import__("sensor_msgs.msg").msg.Range, __import__("rosgraph_msgs.msg").msg.Log):
        pkg, name = cls._type.split("/")
        assert (cls._full_text, cls._md5sum) == store.generate_msgdef("%s/msg/%s" % (pkg, name), ros_version=1)


def test_str_layout():
    assert str(Twist()) == "linear: \n  x: 0.0\n  y: 0.0\n  z: 0.0\nangular: \n  x: 0.0\n  y: 0.0\n  z: 0.0"
    assert str(Vector3(0.1, 1e-20, 1 / 3)) == "x: 0.1\ny: 1e-20\nz: 0.3333333333333333"
    assert str(String("hi")) == 'data: "hi"' and str(String()) == "data: ''"
    odom = Odometry()
    odom.header.seq, odom.header.stamp, odom.header.frame_id = 7, genpy.Time(12, 500000000), "odom"
    assert str(odom).startswith('header: \n  seq: 7\n  stamp: \n    secs: 12\n    nsecs: 500000000\n  frame_id: "odom"')
    assert "nsecs:         0" in str(Odometry())


def test_serialize_bytes_and_accepted_values():
    assert _bytes(Twist(Vector3(1, 0, 0), Vector3())) == np.array([1, 0, 0, 0, 0, 0], "<f8").tobytes()
    for value in (1, True, np.float64(0.5), np.float32(0.5), np.int64(3), np.array(0.5), 1e400, float("nan")):
        _bytes(Twist(linear=Vector3(x=value)))
    assert _bytes(String("hi")) == b"\x02\x00\x00\x00hi"


@pytest.mark.parametrize("bad", ["fast", None, "0.5", [1], 1j])
def test_bad_float_names_the_field(bad):
    t = Twist()
    t.linear.x = bad
    with pytest.raises(SerializationError, match="^field linear.x must be float type$"):
        _bytes(t)


def test_string_field_check_and_import_path():
    from genpy.message import SerializationError as same
    assert same is genpy.SerializationError
    with pytest.raises(SerializationError, match="^field data must be of type bytes or an ascii string$"):
        _bytes(String(data=5))


def test_deserialize_roundtrip():
    odom = Odometry(child_frame_id="base")
    odom.pose.pose.position.x = 1.5
    odom.header.stamp = genpy.Time(3, 4)
    back = Odometry().deserialize(_bytes(odom))
    assert (back.pose.pose.position.x, back.header.stamp, back.child_frame_id) == (1.5, genpy.Time(3, 4), "base")
    assert back.pose.covariance == (0.0,) * 36  # genpy returns fixed arrays as tuples
    with pytest.raises(genpy.DeserializationError, match="unpack requires a buffer of 48 bytes"):
        Twist().deserialize(b"\x05\x00")


def test_classes_are_the_same_however_imported():
    from geometry_msgs.msg._Twist import Twist as deep
    from std_srvs.srv import Empty, EmptyRequest, EmptyResponse
    assert deep is Twist is geometry_msgs.msg.Twist
    assert Odometry().pose.pose.position.__class__ is geometry_msgs.msg.Point
    assert Empty._request_class is EmptyRequest and Empty._response_class is EmptyResponse
    assert Empty._md5sum == "d41d8cd98f00b204e9800998ecf8427e"


def test_twist_serialize_is_fast():
    t, buff = Twist(Vector3(0.2, 0, 0), Vector3(0, 0, 0.5)), io.BytesIO()
    start = time.perf_counter()
    for _ in range(10_000):
        t.serialize(buff)
    assert time.perf_counter() - start < 0.5  # the runtime needs ~1 kHz; this is well over 20 kHz
