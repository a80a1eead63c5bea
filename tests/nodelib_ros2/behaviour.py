"""Observations of rosgrade's ROS 2 message runtime alone (no real ROS needed); prints a JSON object name -> value."""
from __future__ import annotations

import array
import json
import struct
import time


def attempt(fn) -> object:
    try:
        return fn()
    except BaseException as exc:  # noqa: BLE001 - the exception is the observation
        return f"{type(exc).__name__}: {exc}"


def main() -> None:
    start = time.perf_counter()
    from geometry_msgs.msg import TwistStamped  # noqa: F401 - timed
    from nav_msgs.msg import Odometry
    import_ms = (time.perf_counter() - start) * 1000

    import geometry_msgs.msg
    import numpy
    import rosgrade_rosidl as rr
    from geometry_msgs.msg import PoseWithCovariance, Twist, Vector3
    from rcl_interfaces.msg import Log
    from sensor_msgs.msg import LaserScan
    from std_msgs.msg import Empty, Float32, Int32, String, UInt8
    from std_srvs.srv import Empty as EmptySrv, SetBool

    def setter(value):
        v = Vector3(check_fields=True)
        v.x = value

    def int_in_float():
        v = Vector3()
        v.x = 1
        return struct.unpack_from("<d", rr.serialize(v), 4)[0]

    def wrapped(cls, value):
        m = cls()
        m.data = value
        return rr.serialize(m).hex()

    out = {
        "import_ms": import_ms,
        "repr": repr(Vector3()),
        "module_attr": geometry_msgs.msg.Twist is Twist,
        "dir": "TwistStamped" in dir(geometry_msgs.msg),
        "unknown_name": attempt(lambda: geometry_msgs.msg.Nope),
        "bad_kwarg_default": attempt(lambda: repr(Vector3(foo=1))),
        "bad_kwarg_checked": attempt(lambda: Vector3(foo=1, bar=2, check_fields=True)),
        "setter_int": attempt(lambda: setter(1)),
        "setter_str": attempt(lambda: setter("a")),
        "setter_range": attempt(lambda: setattr(UInt8(check_fields=True), "data", 256)),
        "setter_f32_range": attempt(lambda: setattr(Float32(check_fields=True), "data", 1e39)),
        "cov_type": type(PoseWithCovariance().covariance).__name__,
        "cov_dtype": str(PoseWithCovariance().covariance.dtype),
        "ranges_type": type(LaserScan().ranges).__name__,
        "ranges_list_set": repr(LaserScan(ranges=[1.0, 2.0]).ranges),
        "eq": [Twist() == Twist(), Twist() == Vector3(), Odometry() == Odometry()],
        "eq_one_cov": (lambda a, b: (b.covariance.__setitem__(0, 1.0), a == b)[1])(PoseWithCovariance(),
                                                                                    PoseWithCovariance()),
        "fields": Twist.get_fields_and_field_types(),
        "fields_copy": Twist.get_fields_and_field_types() is not Twist._fields_and_field_types,
        "log_info": [Log.INFO, Log().ERROR],
        "empty": [repr(Empty()), rr.serialize(Empty()).hex()],
        "type_name": [rr.type_name(Odometry), rr.type_name(Odometry()), rr.type_name(SetBool)],
        "type_hash": rr.type_hash(Twist),
        "srv": [repr(SetBool.Request(data=True)), SetBool.Response.__name__, EmptySrv.Event.__name__,
                attempt(EmptySrv)],
        "type_support": [type(Twist)._TYPE_SUPPORT is None,
                         (type(Twist).__import_type_support__(), type(Twist)._TYPE_SUPPORT is not None)[1]],
        "int_in_float": int_in_float(),
        "i32_float": attempt(lambda: wrapped(Int32, 1.5)),
        "u8_wrap": wrapped(UInt8, 300),
        "str_int": attempt(lambda: wrapped(String, 5)),
        "decode_header": attempt(lambda: rr.deserialize(Twist, b"\x00\x00\x00\x00" + bytes(48))),
        "decode_short": attempt(lambda: rr.deserialize(Twist, rr.serialize(Twist())[:-1])),
        "decode_huge_count": attempt(lambda: rr.deserialize(LaserScan, b"\x00\x01\x00\x00" + bytes(40)
                                                            + b"\xff\xff\xff\x7f")),
        "decode_padded": repr(rr.deserialize(Vector3, rr.serialize(Vector3(x=2.0)) + b"\x55\x55\x55\x55")),
        "decoded_types": (lambda m: [type(m.ranges).__name__, m.ranges.typecode, type(m.header.frame_id).__name__])(
            rr.deserialize(LaserScan, rr.serialize(LaserScan(ranges=array.array("f", [1.0]))))),
        "decoded_cov": (lambda m: [type(m.pose.covariance).__name__, str(m.pose.covariance.dtype),
                                   m.pose.covariance.flags.writeable])(rr.deserialize(Odometry, rr.serialize(
                                       Odometry(pose=PoseWithCovariance(covariance=numpy.ones(36)))))),
    }
    print(json.dumps(out))


if __name__ == "__main__":
    main()
