"""Probe expressions run under real ROS 1 and under rosgrade's nodelib; each prints one canonical JSON line.

Run as a script (``python probes.py``) with either stack importable; the conformance test compares the outputs.
Each probe is a snippet whose last line is an expression; its value (or exception) is rendered canonically so that
numpy versions and object addresses do not matter.
"""
from __future__ import annotations

import json
import math

PI = math.pi
_MSG = "from std_msgs.msg import *\nfrom geometry_msgs.msg import *\nfrom nav_msgs.msg import *\n"
_AXES = ["sxyz", "sxyx", "sxzy", "sxzx", "syzx", "syzy", "syxz", "syxy", "szxy", "szxz", "szyx", "szyz",
         "rzyx", "rxyx", "ryzx", "rxzx", "rxzy", "ryzy", "rzxy", "ryxy", "ryxz", "rzxz", "rxyz", "rzyz"]


def _ser(expr: str) -> str:
    return "import io\n_b = io.BytesIO()\n(%s).serialize(_b)\n_b.getvalue()" % expr


PROBES: list[str] = [
    # constructors and defaults
    "Twist(Vector3(1,2,3), Vector3(4,5,6))", "Twist(Vector3(1,0,0))", "Twist(Vector3(1,0,0), linear=1)",
    "Twist(foo=1)", "Vector3(1,2)", "Vector3(1,2,3,4)", "Vector3(None, 1, 2)", "Twist(linear=None)",
    "Quaternion()", "Float64(3).data", "Vector3(1,2,3)", "Odometry().pose.covariance", "Header().stamp",
    "type(Header().stamp).__name__", "UInt8MultiArray().data", "String().data", "Bool().data",
    "Twist.__slots__", "Twist._slot_types", "Odometry._slot_types", "Twist._type", "Odometry._has_header",
    "Twist._has_header", "TwistStamped._has_header", "Twist().__getstate__()", "Twist()._get_types()",
    "t = Twist()\nt.foo = 1", "t = Twist()\nt.linear = 5\nt.linear", "Twist().__dict__", "hash(Twist())",
    "Twist() == Twist()", "Twist() != Twist()", "Vector3(1,0,0) == Vector3(1.0,0,0)", "Vector3(1,0,0) == Point(1,0,0)",
    "Twist() == 0", "Empty() == Empty()", "bool(Empty())", "Twist.__module__", "Twist.__name__",
    "import pickle\npickle.loads(pickle.dumps(Odometry()))", "import copy\ncopy.deepcopy(Header(stamp=genpy.Time(1,2)))",
    # str()/repr()
    "str(Twist())", "repr(Twist()) == str(Twist())", "str(Odometry())", "str(Empty())", "str(Bool())",
    "str(Vector3(x=0.1, y=1e-20, z=1/3))", "str(String(data='hi'))", "str(String())", "str(String(data='a: b'))",
    "str(String(data='multi\\nline'))", "str(String(data='h\\xe9llo \\u2603'))", "str(String(data=b'hi'))",
    "str(String(data=5))", "str(Header(stamp=genpy.Time(12, 500000000), seq=7, frame_id='odom'))",
    "str(Header(stamp=genpy.Time(1234567890, 123)))", "str(Twist(linear=5))",
    "str(Path(poses=[PoseStamped(), PoseStamped()]))", "str(UInt8MultiArray(data=b'ab'))",
    "str(Float64MultiArray(data=[0.1, 2, True]))", "str(Float64MultiArray(data=(0.5,)))",
    "from sensor_msgs.msg import JointState\nstr(JointState(name=['a', 'a: b', '', 'true', '1.5', 'x y']))",
    "str(Float64MultiArray(layout=MultiArrayLayout(dim=[MultiArrayDimension(label='x', size=2, stride=2)])))",
    "v = Vector3()\nv.x = None\nv.y = 'str'\nv.z = [1, 2]\nstr(v)", "str(Duration(data=genpy.Duration(-1, 5)))",
    "str(Vector3(x=-0.0, y=1e16, z=123456789.123))",
    # serialization
    _ser("Twist(Vector3(1,2,3), Vector3(4,5,6))"), _ser("Twist()"), _ser("String(data='hello')"),
    _ser("String(data='h\\xe9llo')"), _ser("Odometry(child_frame_id='base', header=Header(seq=3, frame_id='odom', stamp=genpy.Time(5, 6)))"),
    _ser("Path(poses=[PoseStamped(), PoseStamped()])"), _ser("OccupancyGrid(data=[1, -2, 100])"),
    _ser("UInt8MultiArray(data=[1, 2])"), _ser("UInt8MultiArray(data=b'ab')"), _ser("Bool(data=True)"),
    _ser("Header(stamp=genpy.Duration(1))"), _ser("Int64(data=-5)"), _ser("UInt64(data=2**64-1)"),
    _ser("Float32(data=1e400)"), _ser("ColorRGBA(1, 0.5, 0.25, 1)"),
    "from tf2_msgs.msg import TFMessage\n" + _ser("TFMessage([TransformStamped(child_frame_id='b')])"),
    "from sensor_msgs.msg import LaserScan\n" + _ser("LaserScan(ranges=[1.0, 2.5], angle_max=3.0)"),
    "from sensor_msgs.msg import JointState\n" + _ser("JointState(name=['a', 'bc'], position=[1.0])"),
    "from rosgraph_msgs.msg import Log\n" + _ser("Log(level=Log.INFO, msg='m', topics=['/a'])"),
    "from rosgraph_msgs.msg import Clock\n" + _ser("Clock(genpy.Time(3, 4))"),
    # accepted values and field checks
    *[_ser("Twist(linear=Vector3(x=%s))" % v) for v in
      ("1", "True", "np.float64(0.5)", "np.float32(0.5)", "np.int64(3)", "np.array(0.5)", "1e400", "float('nan')",
       "'fast'", "None", "'0.5'", "[1]", "1j", "np.array([1.0, 2.0])")],
    "t = Twist()\nt.linear.x = None\n" + _ser("t"), "t = Twist()\nt.linear = None\n" + _ser("t"),
    _ser("Twist(linear=Vector3(x=np.float32(1), y='fast'))"), _ser("String(data=5)"), _ser("String(data=b'hi')"),
    "s = String()\ns.data = None\n" + _ser("s"), _ser("Int32(data=1.5)"), _ser("Int32(data=2**40)"),
    _ser("UInt8(data=-1)"), _ser("UInt8(data=300)"), _ser("Int32(data=True)"), _ser("Bool(data='x')"),
    _ser("Odometry(pose=PoseWithCovariance(covariance=['a'] * 36))"), _ser("Path(poses=[1])"),
    _ser("OccupancyGrid(data=[1, 2, 300])"), _ser("UInt8MultiArray(data=5)"),
    "from sensor_msgs.msg import JointState\n" + _ser("JointState(name=['a', 5])"),
    "h = Header()\nh.seq = -1\n" + _ser("h"), _ser("Char(data='a')"),
    # deserialization
    "Twist().deserialize(bytes(range(48)))", "Odometry().deserialize(%r)" % (b"\x01\x00\x00\x00" * 3 + b"\x00" * 688,),
    "Odometry().deserialize(%r).pose.covariance" % (b"\x00" * 700,), "String().deserialize(b'\\x02\\x00\\x00\\x00ab').data",
    "Twist().deserialize(b'\\x05\\x00')", "OccupancyGrid().deserialize(b'\\x00' * 92 + b'\\x02\\x00\\x00\\x00\\x01\\xfe').data",
    "UInt8MultiArray().deserialize(b'\\x00' * 8 + b'\\x02\\x00\\x00\\x00\\x01\\x02').data",
    "Bool().deserialize(b'\\x02').data", "Header().deserialize(b'\\x00' * 8 + b'\\x00\\xca\\x9a\\x3b' + b'\\x00' * 4).stamp",
    "Path().deserialize(b'\\x00' * 12 + b'\\x00\\x00\\x00\\x00' + b'\\x01\\x00\\x00\\x00' + b'\\x00' * 72).poses",
    # md5 sums and metadata
    *["import %s.msg as m\nm.%s._md5sum" % tuple(t.split("/")) for t in (
        "std_msgs/Bool", "std_msgs/Byte", "std_msgs/Char", "std_msgs/ColorRGBA", "std_msgs/Duration", "std_msgs/Empty",
        "std_msgs/Float32", "std_msgs/Float64", "std_msgs/Header", "std_msgs/Int8", "std_msgs/Int16", "std_msgs/Int32",
        "std_msgs/Int64", "std_msgs/UInt8", "std_msgs/UInt16", "std_msgs/UInt32", "std_msgs/UInt64", "std_msgs/String",
        "std_msgs/Time", "std_msgs/Float64MultiArray", "std_msgs/Int32MultiArray", "std_msgs/UInt8MultiArray",
        "std_msgs/ByteMultiArray", "std_msgs/MultiArrayLayout", "geometry_msgs/Point", "geometry_msgs/Point32",
        "geometry_msgs/Pose", "geometry_msgs/Pose2D", "geometry_msgs/PoseStamped", "geometry_msgs/PoseArray",
        "geometry_msgs/PoseWithCovariance", "geometry_msgs/PoseWithCovarianceStamped", "geometry_msgs/Quaternion",
        "geometry_msgs/QuaternionStamped", "geometry_msgs/Transform", "geometry_msgs/TransformStamped",
        "geometry_msgs/Twist", "geometry_msgs/TwistStamped", "geometry_msgs/TwistWithCovariance",
        "geometry_msgs/TwistWithCovarianceStamped", "geometry_msgs/Vector3", "geometry_msgs/Vector3Stamped",
        "geometry_msgs/Accel", "geometry_msgs/AccelStamped", "geometry_msgs/Wrench", "geometry_msgs/WrenchStamped",
        "geometry_msgs/PointStamped", "geometry_msgs/Inertia", "geometry_msgs/Polygon", "geometry_msgs/PolygonStamped",
        "nav_msgs/Odometry", "nav_msgs/Path", "nav_msgs/OccupancyGrid", "nav_msgs/MapMetaData", "nav_msgs/GridCells",
        "sensor_msgs/Imu", "sensor_msgs/LaserScan", "sensor_msgs/JointState", "sensor_msgs/BatteryState",
        "sensor_msgs/Range", "tf2_msgs/TFMessage", "rosgraph_msgs/Log", "rosgraph_msgs/Clock")],
    *["import std_srvs.srv as s\n(s.%s._type, s.%s._md5sum, s.%sRequest._type, s.%sRequest._md5sum, "
      "s.%sResponse._md5sum, s.%sResponse.__slots__, s.%s._request_class is s.%sRequest)" % ((n,) * 8)
      for n in ("Empty", "Trigger", "SetBool")],
    "from std_srvs.srv import TriggerResponse\nstr(TriggerResponse(True, 'done'))",
    "from sensor_msgs.msg import BatteryState, Range\n(BatteryState.POWER_SUPPLY_STATUS_FULL, Range.INFRARED, BatteryState.__slots__)",
    "from rosgraph_msgs.msg import Log\n(Log.DEBUG, Log.FATAL, Log._has_header)",
    "from geometry_msgs.msg._Twist import Twist as T\nT is Twist",
    # Time and Duration
    *["genpy." + e if e[0] in "TD" else e for e in (
        "Time(5, 2500)", "Time(1.5)", "(Time(1.5).secs, Time(1.5).nsecs)", "Time(0, 1500000000)", "Time(-1)",
        "Time(0, -1)", "Time(1, -1)", "Time(1.5, 3)", "Time('1')", "Time(None)", "Time.from_sec(12.345678901)",
        "Time.from_sec(1700000000.123456789).nsecs", "Time.from_sec(-1)", "str(genpy.Time(1, 500000000))",
        "'%s' % genpy.Time(1, 5)", "Time(1, 5).to_sec()", "Time(1, 5).to_nsec()", "Time(1, 5).to_time()",
        "Time(10) + genpy.Duration(1.5)", "Duration(1.5) + genpy.Time(10)", "Time(10) - genpy.Time(8, 5)",
        "Time(10) - genpy.Duration(1)", "Time(1) - genpy.Duration(2)", "Time(10) + genpy.Time(1)", "Time(1) + 1.0",
        "Time(1) - 1.0", "Duration(1) + 1.0", "1.0 + genpy.Duration(1)", "Duration(1) > 0.5", "Time(1) < 2",
        "Time(1) == 1", "Time(1) == genpy.Time(1)", "Time(1) == genpy.Duration(1)", "Duration(1) * 3",
        "Duration(1) * 1.5", "3 * genpy.Duration(1)", "Duration(3) / 2", "Duration(3) / 2.0", "Duration(3) // 2",
        "Duration(3) / genpy.Duration(2)", "Duration(3) // genpy.Duration(2)", "Duration(3) % genpy.Duration(2)",
        "divmod(genpy.Duration(3), genpy.Duration(2))", "-genpy.Duration(3)", "abs(genpy.Duration(-3))",
        "(genpy.Duration(-0.5).secs, genpy.Duration(-0.5).nsecs)", "Duration.from_sec(-1.25).secs",
        "Duration.from_sec(-1.25).nsecs", "bool(genpy.Time(0))", "bool(genpy.Duration(0))", "Time(0).is_zero()",
        "float(genpy.Time(1, 5))", "hash(genpy.Time(3)) == hash(genpy.Time(3))", "Duration(3) / 0",
        "Duration(3) // 0", "Time(3) * 2", "Duration(-1, -1)", "Duration(0, -1500000000)", "str(genpy.Duration(-0.5))",
        "repr(genpy.Duration(1, 5))", "Duration(7) / 3", "Duration(-7) // 2", "Duration(2) * 0.333333333",
        "Duration(1) * (1 / 3)", "Duration(7) % genpy.Duration(-2)", "Time(1.000000005).nsecs", "Time(1, 1.5)",
        "Duration(-0.3).nsecs", "Time(1, 5).__getstate__()", "sorted([genpy.Duration(2), genpy.Duration(-1)])",
        "Time(1).__cmp__(3)", "Time(float('nan'))", "Duration(float('inf'))", "Duration(True)", "Duration(3) * 'a'",
        "Time(1, 5)._slot_types", "Duration(1.5).to_sec()", "Duration(-3, 5).to_nsec()", "Time(3e9).secs",
        "import pickle\npickle.loads(pickle.dumps(genpy.Time(4, 5)))")],
    # tf.transformations
    "tft.euler_from_quaternion([0, 0, 0, 1])", "tft.euler_from_quaternion([0, 0, math.sin(PI/4), math.cos(PI/4)])",
    "tft.euler_from_quaternion([0, 0, 1, 0])", "tft.euler_from_quaternion([0, 0, -1, 0])",
    "tft.euler_from_quaternion([0, 0, 0, -1])", "tft.euler_from_quaternion([0, 0, 0.7071, 0.7071])",
    "tft.euler_from_quaternion([0, 0, 2 * math.sin(PI/4), 2 * math.cos(PI/4)])", "tft.euler_from_quaternion([0, 0, 0, 0])",
    "tft.euler_from_quaternion(Quaternion(0, 0, 0, 1))", "tft.euler_from_quaternion([0, 0, 1])",
    "tft.euler_from_quaternion((0.1, 0.2, 0.3, 0.9))", "tft.euler_from_quaternion(np.array([0.1, -0.2, 0.3, 0.9]))",
    "tft.euler_from_quaternion([0, 0, 0, 1], 'abc')", "tft.euler_from_quaternion([0, 0, 0, 1], (0, 0, 0, 0))",
    "tft.quaternion_from_euler(0, 0, 0)", "tft.quaternion_from_euler(0, 0, PI/2)", "tft.quaternion_from_euler(0, 0, PI)",
    "tft.quaternion_from_euler(0, 0, -PI)", "tft.quaternion_from_euler(0, 0, 3*PI/2)", "tft.quaternion_from_euler(0.1, 0.2, 0.3)",
    *["tft.euler_from_quaternion(tft.quaternion_from_euler(0, 0, %s))" % y for y in ("PI", "-PI", "4.0", "-3.5", "0.5")],
    *["(tft.quaternion_from_euler(0.1, -0.7, 2.5, %r), tft.euler_from_quaternion(tft.quaternion_from_euler(0.1, -0.7, 2.5, %r), %r), "
      "tft.euler_matrix(0.3, 0.2, -1.1, %r), tft.euler_from_matrix(tft.euler_matrix(0.3, 1.2, -1.1, %r), %r))" % ((a,) * 6)
      for a in _AXES],
    "tft.euler_from_quaternion(tft.quaternion_from_euler(0, 0, PI/2, 'rzyx'), 'rzyx')",
    "tft.quaternion_multiply([0.1, 0.2, 0.3, 0.9], [-0.4, 0.5, 0.1, 0.7])", "tft.quaternion_conjugate([0.1, 0.2, 0.3, 0.9])",
    "tft.quaternion_inverse([0.1, 0.2, 0.3, 0.9])", "tft.quaternion_matrix([0.1, 0.2, 0.3, 0.9])",
    "tft.quaternion_from_matrix(tft.euler_matrix(0.3, 0.2, -1.1))", "tft.quaternion_from_matrix(tft.rotation_matrix(3.0, [1, 0, 0]))",
    "tft.quaternion_from_matrix(tft.rotation_matrix(3.0, [0, 1, 0]))", "tft.quaternion_from_matrix(tft.rotation_matrix(3.0, [0, 0, 1]))",
    "tft.rotation_matrix(0.5, [1, 2, 3])", "tft.rotation_matrix(0.5, [0, 0, 1], [1, 1, 0])", "tft.identity_matrix()",
    "tft.translation_matrix([1, 2, 3])", "tft.translation_from_matrix(tft.translation_matrix([1, 2, 3]))",
    "tft.quaternion_about_axis(0.5, [1, 2, 3])", "tft.quaternion_about_axis(0.5, [0, 0, 0])",
    "tft.random_quaternion([0.1, 0.5, 0.9])", "tft.unit_vector([1, 2, 3])", "tft.unit_vector([[1, 2], [3, 4]], axis=1)",
    "tft.vector_norm([1, 2, 3])", "tft.vector_norm([[1, 2], [3, 4]], axis=0)",
    "tft.quaternion_slerp([0, 0, 0, 1], [0, 0, 1, 0], 0.3)", "tft.quaternion_slerp([0, 0, 0, 1], [0, 0, -0.6, 0.8], 0.5)",
    "tft.quaternion_slerp([0, 0, 0, 1], [0, 0, 1, 0], 0.0)", "tft.concatenate_matrices(tft.translation_matrix([1, 0, 0]), tft.euler_matrix(0, 0, 1))",
    "tft.concatenate_matrices()", "tft.inverse_matrix(tft.euler_matrix(0.1, 0.2, 0.3))", "tft.scale_matrix(2.0, [1, 1, 1])",
    "tft.scale_matrix(2.0, None, [0, 0, 1])", "tft.reflection_matrix([0, 0, 0], [1, 0, 0])",
    "tft.is_same_transform(tft.identity_matrix(), tft.identity_matrix() * 2)", "tft.random_rotation_matrix([0.2, 0.4, 0.6])",
    "tf.transformations is tft", "(tf.Exception.__name__, tf.LookupException.__mro__[1].__name__, tf.ExtrapolationException.__module__)",
    # tf.Transformer (no ROS master needed)
    *["tr = tf.Transformer(True)\nfor c, p, s, x in [('base', 'odom', 10, 1.0), ('base', 'odom', 11, 2.0), ('x', 'map', 11, 2.0), ('laser', 'base', 10.5, 0.5)]:\n"
      "    m = TransformStamped()\n    m.header.frame_id, m.child_frame_id, m.header.stamp = p, c, genpy.Time(s)\n"
      "    m.transform.translation.x = x\n    m.transform.rotation.z, m.transform.rotation.w = math.sin(x / 4), math.cos(x / 4)\n"
      "    tr.setTransform(m)\n" + e for e in (
          "tr.lookupTransform('odom', 'base', genpy.Time(0))", "tr.lookupTransform('odom', 'base', genpy.Time(10, 500000000))",
          "tr.lookupTransform('base', 'odom', genpy.Time(12))", "tr.lookupTransform('odom', 'base', genpy.Time(9))",
          "tr.lookupTransform('odom', 'nope', genpy.Time(0))", "tr.lookupTransform('nope', 'base', genpy.Time(0))",
          "tr.lookupTransform('odom', 'x', genpy.Time(0))", "tr.lookupTransform('/odom', 'base', genpy.Time(0))",
          "tr.lookupTransform('odom', 'laser', genpy.Time(10, 500000000))", "tr.lookupTransform('odom', 'laser', genpy.Time(0))",
          "tr.lookupTransform('odom', 'laser', genpy.Time(10, 700000000))",
          "(tr.canTransform('odom', 'base', genpy.Time(0)), tr.canTransform('odom', 'x', genpy.Time(0)), tr.frameExists('odom'), tr.frameExists('base'), tr.getFrameStrings())",
          "tr.lookupTransform('odom', 'odom', genpy.Time(0))")],
]


def render(value):
    """A JSON-able canonical form: type-tagged, independent of numpy's repr and object addresses."""
    try:
        import numpy as np
    except ImportError:  # pragma: no cover
        np = None
    if np is not None and isinstance(value, np.ndarray):
        return ["ndarray", str(value.dtype), list(value.shape), [render(v) for v in value.ravel().tolist()]]
    if np is not None and isinstance(value, np.generic):
        return ["np." + type(value).__name__, render(value.item())]
    if isinstance(value, float):
        return ["float", repr(value)]
    if isinstance(value, (bool, int, str, type(None))):
        return value
    if isinstance(value, bytes):
        return ["bytes", value.hex()]
    if isinstance(value, (list, tuple)):
        return [type(value).__name__, [render(v) for v in value]]
    if isinstance(value, dict):
        return ["dict", sorted((repr(k), render(v)) for k, v in value.items())]
    cls = type(value)
    return ["%s.%s" % (cls.__module__.split(".")[0], cls.__name__), repr(value)]


def run(snippet: str):
    """Execute snippet and render the value of its last line, or the exception it raised."""
    import ast
    import numpy as np
    import genpy
    import tf
    import tf.transformations as tft
    env = {"np": np, "genpy": genpy, "tf": tf, "tft": tft, "math": math, "PI": PI}
    exec(_MSG, env)
    try:
        tree = ast.parse(snippet)
        last = tree.body[-1]
        exec(compile(ast.Module(tree.body[:-1], []), "<probe>", "exec"), env)
        if isinstance(last, ast.Expr):
            return ["ok", render(eval(compile(ast.Expression(last.value), "<probe>", "eval"), env))]
        exec(compile(ast.Module([last], []), "<probe>", "exec"), env)
        return ["ok", None]
    except BaseException as error:  # noqa: BLE001 - every outcome is data here
        return ["raise", type(error).__name__, str(error)]


if __name__ == "__main__":
    import warnings
    warnings.simplefilter("ignore")
    for probe in PROBES:
        print(json.dumps(run(probe)))
