"""The conformance probes: how each is run, and the behaviour values from the reference each must show.

The expected lines come from /work/shared/reference/rospy-behaviour.md (real rospy 1.15.15 under a paced sim clock)
and were re-checked with real_ros.py. They are written in normalised form (see conformance_compare): times as
``t=<s>`` relative to the probe's origin, log lines as ``[LEVEL] [<wall>, t=<s>]: msg``, probe paths as
``<probe>/pNN_x.py``, library traceback frames as ``<library frames>``, addresses as ``0xADDR``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

PROBES_DIR = Path(__file__).resolve().parent / "probes"
INIT_ERR = "rospy.exceptions.ROSInitException: time is not initialized. Have you called init_node()?"
REQUEST = "rospy.exceptions.ROSInterruptException: ROS shutdown request"


@dataclass(frozen=True)
class Case:
    id: str
    script: str
    args: tuple[str, ...] = ()
    shutdown_at: float | None = None   # sim s after the start (ours) / after the first clock tick (real)
    duration: float = 4.0
    ros_namespace: str | None = None
    compare_commands: bool = False
    exit_code: int = 0
    stdout: tuple[str, ...] = ()       # lines that must appear, in this order
    stderr: tuple[str, ...] = ()
    stderr_empty: bool = False
    # Sim-time tolerance when comparing the two sides; one clock step unless the probe's timing depends on
    # something the real side cannot pin down (the phase of the 30 Hz odometry against the probe's origin).
    tolerance_s: float = 0.01
    notes: tuple[str, ...] = field(default=())
    # (a line the real library logs when a race between its own threads hit the run, why): such a real run is no
    # reference, as the real library's own behaviour then depends on the machine's load; rosgrade models the run
    # the race did not hit.
    real_race: tuple[str, str] = ("", "")

    @property
    def path(self) -> Path:
        return PROBES_DIR / self.script


CASES = [
    Case("p01_time", "p01_time.py", stdout=(
        f"before_init Time.now !! {INIT_ERR}",
        f"before_init get_time !! {INIT_ERR}",
        f"before_init get_rostime !! {INIT_ERR}",
        f"before_init Rate !! {INIT_ERR}",
        "before_init spin !! rospy.exceptions.ROSInitException: client code must call rospy.init_node() first",
        "before_init is_shutdown False",
        "before_init sleep(0.01) returned",
        "after_init now_is_zero True get_time 0.0 type Time",
        "after_init now_is_now True",
        "rate created at time zero True remaining rospy.Duration[100000000]",
        "after_first_sleep now_is_zero False",
        "now_is_now True now_eq_rostime True",
        "time_type Time float",
        "T0_on_clock_grid True",
        "rate_at_zero iter 0 t=0.000",
        "rate_at_zero iter 1 t=0.000",
        "rate_at_zero iter 2 t=0.100",
        "rate_at_zero iter 3 t=0.200",
        "rate_at_zero iter 4 t=0.300",
        "rospy.sleep(0.3) advanced 0.30",
        "rospy.sleep(0) advanced 0.00",
        "rospy.sleep(-1) advanced 0.00",
        "rospy.sleep(Duration 0.15) advanced 0.15",
        "rate_running iter 0 t=0.850",
        "rate_running iter 1 t=0.950",
        "rate_running iter 2 t=1.050",
        "rate_running remaining_in_range True",
        "smallest step 0.01 all steps multiples of 10 ms True",
        "time.sleep(0.3) advanced about 0.3",
    ), stderr_empty=True),
    Case("p02_time_arith", "p02_time_arith.py", duration=2.0, stdout=(
        "Time(5, 2500) -> rospy.Time[5000002500] (Time)",
        "str(Time(5, 2500)) -> '5000002500' (str)",
        "(Time(1.5).secs, Time(1.5).nsecs) -> (1, 500000000) (tuple)",
        "(Time(0, 1500000000).secs, Time(0, 1500000000).nsecs) -> (1, 500000000) (tuple)",
        "Time(-1) !! builtins.TypeError: time values must be positive",
        "(Time.from_sec(12.345678901).secs, Time.from_sec(12.345678901).nsecs) -> (12, 345678900) (tuple)",
        "Time.from_sec(1700000000.123456789).nsecs -> 123456716 (int)",
        "Time(10) + Duration(1.5) -> rospy.Time[11500000000] (Time)",
        "Duration(1.5) + Time(10) -> rospy.Time[11500000000] (Time)",
        "Time(10) - Time(8, 5) -> genpy.Duration[1999999995] (Duration)",
        "Time(10) - Duration(1) -> rospy.Time[9000000000] (Time)",
        "Time(1) + Time(1) !! builtins.TypeError: unsupported operand type(s) for +: 'Time' and 'Time'",
        "Duration(1) > 0.5 !! builtins.TypeError: '>' not supported between instances of 'Duration' and 'float'",
        "Duration(3) / Duration(2) -> 1.5 (float)",
        "(Duration(-0.5).secs, Duration(-0.5).nsecs) -> (-1, 500000000) (tuple)",
        "(Duration.from_sec(-1.25).secs, Duration.from_sec(-1.25).nsecs) -> (-2, 750000000) (tuple)",
        "float(Time(1, 5)) !! builtins.TypeError: float() argument must be a string or a real number, not 'Time'",
        "Time(1) == Duration(1) -> False (bool)",
        "genpy.Time(3) == Time(3) -> True (bool)",
    ), stderr_empty=True),
    Case("p03_shutdown_uncaught", "p03_shutdown.py", ("uncaught",), shutdown_at=1.05, duration=4.0,
         compare_commands=True, exit_code=1, stdout=(
             "stop() called by on_shutdown(stop())",
             "on_shutdown(stop()) !! TypeError: shutdown hook [None] must be a function or callable object: "
             "<class 'NoneType'>",
             "mro ['ROSInterruptException', 'ROSException', 'Exception', 'KeyboardInterrupt', 'BaseException', 'object']",
             "issubclass(ROSTimeMovedBackwardsException, ROSInterruptException) True",
             "hook1 args () is_shutdown False requested True n 9",
             "hook2 raising",
             "hook3 publishing zero Twist; is_shutdown False",
         ), stderr=(
             "Traceback (most recent call last):",
             "  <library frames>",
             '  File "<probe>/p03_shutdown.py", line 25, in hook2',
             '    raise RuntimeError("boom in hook")',
             "RuntimeError: boom in hook",
             "Traceback (most recent call last):",
             "  <library frames>",
             REQUEST,
         )),
    Case("p03_shutdown_caught", "p03_shutdown.py", ("caught",), shutdown_at=1.05, duration=4.0,
         compare_commands=True, stdout=(
             "hook1 args () is_shutdown False requested True n 9",
             "hook2 raising",
             "hook3 publishing zero Twist; is_shutdown False",
             f"caught {REQUEST}",
             "after loop is_shutdown True n 9",
             "publish after shutdown returns None",
             f"rospy.sleep(0.1) !! {REQUEST}",
             f"rospy.sleep(0) !! {REQUEST}",
             f"rate.sleep() !! {REQUEST}",
             "late hook ran immediately",
             "spin returned; is_shutdown True",
             "end",
         ), stderr=("RuntimeError: boom in hook",)),
    Case("p04_logging", "p04_logging.py", stdout=(
        "print before init",
        "[INFO] [<wall>, 0.000000]: right after init_node",
        "[INFO] [<wall>, t=0.000]: loginfo message",
        "[INFO] [<wall>, t=0.000]: x=1.23 y=2.00",
        "[INFO] [<wall>, t=0.000]: pct-args tuple (1, 2)",
        "[INFO] [<wall>, t=0.000]: literal 100% no args",
        "[INFO] [<wall>, t=0.000]: dict arg 5",
        "[INFO] [<wall>, t=0.000]: 12345",
        "[INFO] [<wall>, t=0.000]: ['a', 1]",
        "[INFO] [<wall>, t=0.000]: x: 1",
        "y: 2",
        "z: 3",
        "[INFO] [<wall>, t=0.000]: multi",
        "line",
        "bad format !! TypeError: %d format: a real number is required, not str",
        "print goes to stdout",
        "name /p04_logging /p04_logging /",
        # throttle compares with a strict '>' on ROS time: a 0.5 s throttle in a 10 Hz loop prints every 6th
        # iteration, a 1.0 s one every 11th (measured; equal times do not print).
        "[INFO] [<wall>, t=0.100]: throttle 0",
        "[INFO] [<wall>, t=0.100]: A0",
        "[INFO] [<wall>, t=0.100]: B0",
        "[INFO] [<wall>, t=0.100]: via helper 0",
        "[INFO] [<wall>, t=0.100]: info once 0",
        "[INFO] [<wall>, t=0.100]: identical",
        "[INFO] [<wall>, t=0.700]: throttle 6",
        "[INFO] [<wall>, t=0.700]: A6",
        "[INFO] [<wall>, t=0.700]: B6",
        "[INFO] [<wall>, t=0.700]: via helper 6",
        "[INFO] [<wall>, t=1.200]: identical",
        "[INFO] [<wall>, t=1.300]: throttle 12",
        "[INFO] [<wall>, t=1.900]: throttle 18",
        "[INFO] [<wall>, t=2.200]: done",
    ), stderr=(
        "logwarn before init_node",
        "logerr before init_node",
        "[WARN] [<wall>, t=0.000]: logwarn message",
        "[ERROR] [<wall>, t=0.000]: logerr message",
        "[FATAL] [<wall>, t=0.000]: logfatal message",
        "[WARN] [<wall>, t=0.000]: warn 7",
        "print to stderr",
        "[WARN] [<wall>, t=0.100]: warn once 0",
        "[WARN] [<wall>, t=0.100]: warn throttle 0",
        "[WARN] [<wall>, t=1.200]: warn throttle 11",
    )),
    Case("p05_messages", "p05_messages.py", duration=2.0, stdout=(
        "meta Twist geometry_msgs/Twist 9f195f881246fdfa2798d1d3eebca84a False ['linear', 'angular'] "
        "['geometry_msgs/Vector3', 'geometry_msgs/Vector3']",
        "meta Vector3 geometry_msgs/Vector3 4a842b65f413084dc2b10fb484ea7f17 False ['x', 'y', 'z'] "
        "['float64', 'float64', 'float64']",
        "meta Odometry nav_msgs/Odometry cd5e73d190d741a2f92e81eda573aca7 True ['header', 'child_frame_id', 'pose', "
        "'twist'] ['std_msgs/Header', 'string', 'geometry_msgs/PoseWithCovariance', 'geometry_msgs/TwistWithCovariance']",
        "meta TFMessage tf2_msgs/TFMessage 94810edda583a504dfda3829e70d7eec False ['transforms'] "
        "['geometry_msgs/TransformStamped[]']",
        "meta String std_msgs/String 992ce8a1687cec8c8bd883ec73ca41d1 False ['data'] ['string']",
        "Twist(Vector3(1,0,0)) !! builtins.TypeError: Invalid number of arguments, args should be ['linear', 'angular'] "
        "args are(x: 1",
        "Twist(Vector3(), angular=Vector3()) !! builtins.TypeError: Message constructor may only use args OR keywords, "
        "not both",
        "Twist(foo=1) !! builtins.AttributeError: foo is not an attribute of Twist",
        "Vector3(1,2) !! builtins.TypeError: Invalid number of arguments, args should be ['x', 'y', 'z'] args are(1, 2)",
        "Float64(3).data -> 3 (int)",
        "Quaternion() -> (0.0, 0.0, 0.0, 0.0) (tuple)",
        "Odometry().header.stamp -> genpy.Time[0] (Time)",
        "t.foo = 1 !! builtins.AttributeError: 'Twist' object has no attribute 'foo'",
        "t.linear = 5 -> 5 (int)",
        "hash(Twist()) !! builtins.TypeError: unhashable type: 'Twist'",
        "str(Twist()):", "linear: ", "  x: 0.0", "  y: 0.0", "  z: 0.0", "angular: ", "  x: 0.0", "  y: 0.0", "  z: 0.0",
        "x: 0.1", "y: 1e-20", "z: 0.3333333333333333",
        "str(String('hi')): data: \"hi\"",
        "str(String()): data: ''",
        "    nsecs: 500000000",
        "    nsecs:         0",
        "serialize linear.x='fast' !! genpy.message.SerializationError: field linear.x must be float type",
        "serialize linear.x=None !! genpy.message.SerializationError: field linear.x must be float type",
        "serialize linear.x=int 2 -> 48 (int)",
        "serialize linear.x=nan -> 48 (int)",
        "serialize String(data=5) !! genpy.message.SerializationError: field data must be of type bytes or an ascii "
        "string",
    ), stderr_empty=True),
    Case("p06_tf", "p06_tf.py", duration=2.0, stdout=(
        "tf.transformations is tft True",
        "euler_from_quaternion([0, 0, 0, 1]) -> tuple [('float', 0.0), ('float', -0.0), ('float', 0.0)]",
        "euler_from_quaternion([0, 0, 1, 0]) -> tuple [('float', 0.0), ('float', -0.0), ('float', 3.141592653589793)]",
        "euler_from_quaternion([0, 0, -1, 0]) -> tuple [('float', 0.0), ('float', 0.0), ('float', 3.141592653589793)]",
        "euler_from_quaternion([0, 0, 0.7071, 0.7071]) -> tuple [('float', 0.0), ('float', -0.0), "
        "('float', 1.5707963267948966)]",
        "euler_from_quaternion([0, 0, 0, 0]) -> tuple [('float', 0.0), ('float', -0.0), ('float', 0.0)]",
        "euler_from_quaternion(Quaternion(0,0,0,1)) !! TypeError: 'Quaternion' object is not subscriptable",
        "euler_from_quaternion([0,0,1]) !! IndexError: index 3 is out of bounds for axis 1 with size 3",
        "quaternion_from_euler(0, 0, 0) -> ndarray float64 (4,) [0.0, 0.0, 0.0, 1.0]",
        "quaternion_from_euler(0, 0, 3.141592653589793) -> ndarray float64 (4,) [0.0, 0.0, 1.0, 6.123233995736766e-17]",
        "quaternion_from_euler(0, 0, -3.141592653589793) -> ndarray float64 (4,) "
        "[0.0, 0.0, -1.0, 6.123233995736766e-17]",
        "round_trip yaw=3.141592653589793 -> tuple [('float', 3.141592653589793)]",
        "round_trip yaw=-3.141592653589793 -> tuple [('float', -3.141592653589793)]",
        "round_trip yaw=4.0 -> tuple [('float', -2.2831853071795867)]",
        "round_trip yaw=-3.5 -> tuple [('float', 2.7831853071795867)]",
        "round_trip yaw=0.5 -> tuple [('float', 0.5000000000000001)]",
        "rzyx yaw pi/2 -> tuple [('float', 1.5707963267948966), ('float', -0.0), ('float', 0.0)]",
    ), stderr_empty=True),
    Case("p07_names_root", "p07_names.py", ("0.2", "extra", "cmd_vel:=/x", "_speed:=0.3"), duration=3.0, stdout=(
        "argv ['0.2', 'extra', 'cmd_vel:=/x', '_speed:=0.3']",
        "myargv before init ['0.2', 'extra']",
        "argv after init ['0.2', 'extra', 'cmd_vel:=/x', '_speed:=0.3']",
        "myargv after init ['0.2', 'extra']",
        "get_name /p07_names get_namespace / caller_id /p07_names",
        "resolve_name('cmd_vel') /x",
        "resolve_name('/cmd_vel') /x",
        "resolve_name('~odom') /p07_names/odom",
        "Publisher('cmd_vel') /x /x geometry_msgs/Twist True",
        "Publisher('/cmd_vel') /x /x geometry_msgs/Twist True",
        "get_param('~speed') 0.3 float",
    ), stderr_empty=True),
    Case("p07_names_ns", "p07_names.py", ("cmd_vel:=/x", "odom:=/bar/odom", "_speed:=0.3", "_flag:=true",
                                          "_text:=hello", "_num:=7", "__name:=renamed"),
         duration=3.0, ros_namespace="robot1", stdout=(
             "myargv before init []",
             "ROS_NAMESPACE robot1",
             "get_name /robot1/renamed get_namespace /robot1/ caller_id /robot1/renamed",
             "resolve_name('cmd_vel') /x",
             "resolve_name('/cmd_vel') /cmd_vel",
             "resolve_name('~odom') /robot1/renamed/odom",
             "resolve_name('odom') /bar/odom",
             "resolve_name('a/b') /robot1/a/b",
             "Publisher('/cmd_vel') /cmd_vel /cmd_vel geometry_msgs/Twist True",
             "get_param('~speed') 0.3 float",
             "get_param('~flag') True bool",
             "get_param('~text') 'hello' str",
             "get_param('~num') 7 int",
         ), stderr_empty=True),
    Case("p08_init_bad", "p08_init.py", ("bad",), duration=3.0, stdout=(
        "get_name before init /unnamed",
        "init_node('/my_node') !! builtins.ValueError: namespaces are not allowed in node names",
        "init_node('robot/my_node') !! builtins.ValueError: namespaces are not allowed in node names",
        "init_node('') !! builtins.ValueError: name must not be empty",
        "init_node('my-node') ok /my-node",
    ), stderr=(
        "<probe>/p08_init.py:26: UserWarning: 'my-node' is not a legal ROS base name. This may cause problems with "
        "other ROS tools.",
    )),
    Case("p08_init_twice", "p08_init.py", ("twice",), duration=3.0, stdout=(
        "init_node('a') ok /a",
        "init_node('a') again ok /a",
        "init_node('b') !! rospy.exceptions.ROSException: rospy.init_node() has already been called with different "
        "arguments: ('a', ['<probe>/p08_init.py', 'twice'], False, None, False, False)",
        "init_node('a', anonymous=True) !! rospy.exceptions.ROSException: rospy.init_node() has already been called "
        "with different arguments: ('a', ['<probe>/p08_init.py', 'twice'], False, None, False, False)",
    )),
    Case("p08_init_anon", "p08_init.py", ("anon",), duration=3.0, stdout=(
        "anonymous name matches /p08_PID_MS True",
        "pid part is os.getpid() True",
        "ms part has 13 digits True",
        "get_name /p08_<PID>_<MS>",
    )),
    Case("p09_callback", "p09_callback.py", tolerance_s=0.05, stdout=(
        "busy wait saw count >= 3 True",
        "callback arg extra",
        "callback callerid /gazebo",
        "callback daemon True",
        "callback main False",
        "callback thread /odom",
        "callback type Odometry",
        "late subscriber got a message True",
        "late subscriber's first message within 0.045 s True",
        "odom stamps in a 1.0 s window 30",
        "tf callbacks > 30 True",
        "main thread MainThread",
    ), stderr=(
        "[ERROR] [<wall>, t=*]: bad callback: <function bad_tf at 0xADDR>",
        "Traceback (most recent call last):",
        "  <library frames>",
        '  File "<probe>/p09_callback.py", line 33, in bad_tf',
        '    raise ValueError("student bug in callback")',
        "ValueError: student bug in callback",
    )),
    Case("p10_publisher", "p10_publisher.py", compare_commands=True, stdout=(
        "published 0 t=zero",
        "published 1 t=0.000",
        "published 2 t=0.000",
        "published 3 t=0.100",
        "published 4 t=0.200",
        "published 22 t=2.000",
    ), stderr_empty=True),
]

# Issue 9, rospy fidelity round 2 (items 1-4, 7-9): each probe is named for what it pins.
_THREAD_LINES = tuple("thread %d t=%.3f" % (i, i / 10) for i in range(12))
CASES += [
    Case("p20_connections", "p20_connections.py", duration=3.0, compare_commands=True,
         # real rospy connects 49-91 ms after the publisher is created (one or two 100 ms waits; ours: one)
         tolerance_s=0.11, stdout=(
             "cmd_vel publisher connections at creation 0",
             "unsubscribed publisher connections at creation 0",
             "waited at least one rate period for the robot to connect True",
             "published once",
             "cmd_vel publisher connections 1",
             "unsubscribed publisher connections after 1 s 0",
             "odom subscriber connections 1",
             "unpublished subscriber connections 0",
         ), stderr_empty=True),
    Case("p21_latch", "p21_latch.py", duration=4.0, compare_commands=True,
         # the robot's connection (and so the latched message) came 0-60 ms after the publisher in real runs
         tolerance_s=0.07, stdout=(
             "published one latched Twist right after creating the publisher",
             "wait_for_message on the latched topic got second",
             "wait_for_message on the plain topic !! timeout exceeded while waiting for message on topic /p21_plain",
             "late subscriber got ['second']",
             "cmd_vel connections 1",
         ), stderr_empty=True),
    Case("p22_thread_spin_rate", "p22_thread.py", ("spin_rate",), shutdown_at=2.0, duration=4.0,
         compare_commands=True, stdout=(*_THREAD_LINES, "thread done True", "main done"), stderr_empty=True),
    Case("p22_thread_sleep_rospy", "p22_thread.py", ("sleep_rospy",), shutdown_at=2.0, duration=4.0,
         compare_commands=True, stdout=(*_THREAD_LINES[:10], "main woke t=1.000", *_THREAD_LINES[10:],
                                        "thread done True", "main done"), stderr_empty=True),
    # time.sleep is wall time in real rospy: 12 sleeps of 0.1 s drift a few ms against the 10 ms clock
    Case("p22_thread_spin_time", "p22_thread.py", ("spin_time",), shutdown_at=2.0, duration=4.0,
         compare_commands=True, tolerance_s=0.02, stdout=(*_THREAD_LINES, "thread done True", "main done"),
         stderr_empty=True),
    # callbacks run during init_node: logging is set up (wall time only: no ROS clock yet), time is not
    Case("p23_init_node", "p23_init_node.py", duration=3.0, compare_commands=True, tolerance_s=0.02, stdout=(
        "[INFO] [<wall>]: a log line from a callback during init_node",
        "callbacks ran before init_node returned True",
        f"rospy time in a callback during init_node !! {INIT_ERR}",
        "publisher created before init_node has connections 1",
        "callbacks after init_node True",
    ), stderr=(
        "[ERROR] [<wall>]: bad callback: <function on_tf at 0xADDR>",
        "Traceback (most recent call last):",
        "  <library frames>",
        '  File "<probe>/p23_init_node.py", line 26, in on_tf',
        "    rospy.Time.now()  # raises: rospy reports it as a bad callback",
        "  <library frames>",
        INIT_ERR,
    )),
    Case("p24_values", "p24_values.py", duration=3.0, compare_commands=True, stdout=(
        "Time(0, 5e8) 0 500000000 int",
        "Duration(1, 2.5e8) 1 250000000 int",
        "published a header stamped Time(0, 5e8)",
        "published numpy scalar and 1-element array values",
        "bad value on an unsubscribed topic: no error",
        "stamp received [(0, 500000000)]",
        "bad value on /cmd_vel !! ROSSerializationException: field linear.x must be float type",
    ), stderr_empty=True),
    Case("p25_shared_subscribers", "p25_shared_subscribers.py", duration=4.0, stdout=(
        "callbacks interleave A,B,A,B True",
        "fast subscriber paced by the slow one True",
        "both called as often True",
        "sys.exit() callback kept being called True",
        "connections 1 1",
    ), stderr_empty=True),
    Case("p26_params", "p26_params.py", duration=2.0, stdout=(
        "use_sim_time before init_node True",
        "tuple reads back as [1, 2.5, 'x'] list",
        "nested tuple reads back as {'a': [1, 2]}",
        "set_param(None) !! builtins.TypeError: cannot marshal None unless allow_none is enabled",
        "has ~none False",
    ), stderr_empty=True),
    # a thread looping until shutdown: Ctrl+C runs the hook (thread still alive), then the thread's rate.sleep() raises
    Case("p27_thread_shutdown", "p27_thread_shutdown.py", shutdown_at=1.55, duration=4.0, compare_commands=True,
         tolerance_s=0.02, stdout=(*_THREAD_LINES[:11], "on_shutdown hook; thread alive True",
                                   "thread caught ROSInterruptException ROS shutdown request",
                                   "thread ended; is_shutdown True", "main done"), stderr_empty=True),
    Case("p28_subscriber_types", "p28_subscriber_types.py", duration=3.0, stdout=(
        "first subscriber got ['Odometry']",
        "second subscriber (declared PoseStamped) got ['Odometry']",
        "declared types Odometry PoseStamped nav_msgs/Odometry geometry_msgs/PoseStamped",
        "connections 1 1",
    ), stderr_empty=True),
    Case("p29_numpy_values", "p29_numpy_values.py", duration=3.0, stdout=(
        "Twist linear.x=np.int64(2) published",
        "Int32 data=np.int64(7) published",
        "Int32 data=np.float64(7.0) !! ROSSerializationException field data must be an integer type",
        "Int32 data=7.5 !! ROSSerializationException field data must be an integer type",
        "String data=np.str_('hi') published",
        "received [('int', 7, 'int'), ('str', 'hi', 'str'), ('twist', 2.0, 'float')]",
    ), stderr_empty=True),
    Case("p30_tf2_geometry", "p30_tf2_geometry.py", duration=2.0, stdout=(
        "point odom 12 500 [1.0, 3.0, 0.75]",
        "vector odom [-2.0, 1.0, 0.0]",
        "pose odom [1.0, 4.0, 0.5] yaw deg 135.0",
        "types PoseStamped PointStamped",
    ), stderr_empty=True),
    Case("p_eco_modules", "p_eco_modules.py", duration=6.0, stdout=(
        "lookup odom base_footprint matches /odom True stamp True",
        "latest stamped True",
        "can_transform 1",
        "can_transform unknown 0",
        'LookupException True "nope" passed to lookupTransform argument source_frame does not exist. ',
        "ExtrapolationException True",
        "own frame probe_static 0.5",
        "own frame probe_moving 0.25",
        "synchronised about 30 in 1 s True",
        "cache holds 5 latest is last True",
        "load_manifest unknown ResourceNotFound no_such_package_here",
        "GetPlan nav_msgs/GetPlan 421c8ea4d21c6c9db7054b4bbdf1e024 6cdd0a18e0aff5b0a3ca2326a89b54ff 0.0",
        "published True True True",
        "remap_name chatter cached True",
        "SubscribeListener ['peer_subscribe', 'peer_unsubscribe']",
    ), stderr_empty=True),
    Case("p_eco_transformations", "p_eco_transformations.py", duration=2.0, stdout=(
        "decompose_matrix [[1.0, 2.0, 3.0], [0.1, 0.2, 0.3], [0.4, -0.5, 0.6], [1.5, -2.5, 3.5], [0.0, 0.0, 0.0, 1.0]]",
        "reflection_from_matrix rebuilds True",
        "rotation_from_matrix rebuilds True",
        "scale_from_matrix rebuilds True",
        "projection_from_matrix rebuilds True",
        "shear_from_matrix angle 0.4",
        "arcball_map_to_sphere [0.25, 0.21875, 0.943211767]",
        "decompose_matrix singular !! Matrix is singular",
    ), stderr_empty=True),
    Case("p_eco_sensors", "p_eco_sensors.py", duration=4.0, stdout=(
        "imu imu_link unit 1.0 9.81 covariances zero True",
        "joint_states ['wheel_left_joint', 'wheel_right_joint'] 2 0 0 ''",
        "scan base_scan 360 0.0 6.28319 0.017502 0.12 3.5 360 all inf True 0.0 0.0",
        "rates about 200, 30, 5 Hz True True True",
    ), stderr_empty=True),
]

# Issue 28 item 8: latched messages for every later subscriber, and one connection (thread, queue) per publisher.
CASES += [
    Case("p31_latched_subscribers", "p31_latched_subscribers.py", duration=4.0, stdout=(
        "first subscriber got ['second']",
        "wait_for_message on the latched topic got second t=1.000",
        "later subscriber got at once [('second', 'arg', 'MainThread', '1', '/p31_latched_subscribers')]",
        "later subscriber of the plain topic got at once []",
        "after a third message: first ['second', 'third'] later ['second', 'third'] newest subscriber ['third']",
        "subscriber after the publisher unregistered got []",
        "wait_for_message on the plain topic !! timeout exceeded while waiting for message on topic /p31_plain",
    ), stderr_empty=True),
    # the first callbacks of both connections come within 0.2 s of the subscription: 7 of 0.3 s each in 2 s
    Case("p32_connection_queues", "p32_connection_queues.py", duration=9.0, stdout=(
        "callbacks in 2 s per publisher [('/gazebo', 7), ('/p32_connection_queues', 7)]",
        "the two publishers' callbacks ran at the same time True",
        "slow subscriber read its backlog whole (queue_size 10 kept) True",
        "fast subscriber called only from the next read on True",
        "fast subscriber called for messages the slow one got True",
        "threads ['/odom']",
        "queue_size 3: the second read's messages are consecutive True",
    ), stderr_empty=True),
    Case("p34_services", "p34_services.py", duration=4.0, stdout=(
        "call before the server !! service [/p34_switch] unavailable",
        "wait_for_service before the server !! timeout exceeded while waiting for service /p34_switch t=0.600",
        "a second Service of the name !! service [/p34_switch] already registered",
        "wait_for_service once served returned t=0.600",
        "handler in the main thread False",
        "response True on within one tick True",
        "handler in the main thread False",
        "handler refused !! service [/p34_switch] responded with an error: b'service cannot process request: no "
        "thanks'",
        "handler in the main thread False",
        "call in a timer callback returned ['on']",
        "call after shutdown !! service [/p34_switch] unavailable",
        "end",
    ), stderr_empty=True),
]

# Issue 33 item 2: when the robot connects to a publisher while the node busy-loops, and while it sleeps. Real rospy's
# connection time is random; measured (wall = sim at 1x, load average 6 on 2 cores): busy 0.024-0.158 s (median 0.08,
# 20 runs; 0.10 from the first line on, 13 runs), polling with rospy.sleep 0.019-0.109 s (median 0.05, 13 runs).
# Ours is 0.10 and 0.05 (test_p33_busy_connect_ours); the real side is compared within 0.06 s, retried.
_P33_LINES = ("connections at creation 0", "end")
CASES += [
    Case(f"p33_busy_connect_{mode}", "p33_busy_connect.py", (mode,), duration=2.0, compare_commands=True,
         tolerance_s=0.06, stdout=_P33_LINES, stderr_empty=True)
    for mode in ("busy", "sleep")
]

# Issue 28: actionlib (Debian's python3-actionlib 1.14) between a SimpleActionServer and a SimpleActionClient of one
# node. Real rospy hands a message to the node's own subscription in well under a clock step, ours one 10 ms step
# later, and wait_for_server returns once the four connections are made (0.06 s real, 0.2 s ours: the publisher
# connection model of p33): log times drift by up to 0.2 s over the probe, hence the tolerance. Real rospy's status
# thread can run a goal's first transition before send_goal has stored the new handle (one more "not tracking" error,
# about 1 run in 5); the harness's retries take the runs without it.
_P35_DONE = "goal {} finished True state {} text {!r} result {}"
CASES += [
    Case("p35_actionlib", "p35_actionlib.py", duration=12.0, tolerance_s=0.3, real_race=(
        "Got a transition callback on a goal handle that we're not tracking",
        "SimpleActionClient.send_goal stores the new goal handle only after ActionClient.send_goal returns; on a "
        "loaded machine the server's first status reaches the client's thread before that, and the goal's active and "
        "later callbacks are dropped with this error (seen in each of 3 real runs during a CI run beside other work)"),
        stdout=(
        "wait_for_server before the server False t=0.300",
        "state with no goal 9 LOST",
        "wait_for_server once started True",
        "execute 3 new goal available False",
        _P35_DONE.format(3, "SUCCEEDED", "counted", 30),
        "  callbacks [('active',), ('feedback', 1), ('feedback', 2), ('feedback', 3), ('done', 'SUCCEEDED', 30)]",
        "preempt requested at 4",
        _P35_DONE.format(10, "PREEMPTED", "stopped", -4),
        "  callbacks [('active',), ('feedback', 1), ('feedback', 2), ('feedback', 3), ('done', 'PREEMPTED', -4)]",
        _P35_DONE.format(-1, "ABORTED", "No terminal state was set.", 0),
        "  callbacks [('active',), ('done', 'ABORTED', 0)]",
        _P35_DONE.format(-2, "ABORTED", "Exception in execute callback: no negative goals", 0),
        "preempt requested at 4",
        "execute 2 new goal available False",
        _P35_DONE.format(2, "SUCCEEDED", "counted", 20),
        "first goal ended PREEMPTED 'stopped'",
        "status list [('SUCCEEDED', 'counted'), ('PREEMPTED', 'stopped'), ('ABORTED', 'No terminal state was set.'), "
        "('ABORTED', 'Exception in execute callback: no negative goals'), ('PREEMPTED', 'stopped'), "
        "('SUCCEEDED', 'counted')]",
        "wait_for_result with no goal False",
        "end",
    )),
]

# Issue 28: actionlib's ActionServer and ActionClient; log times drift by a clock step a hop, as in p35.
_P36_GOAL = "goal {} transitions {} terminal {} text {!r} result {}"
CASES += [
    Case("p36_actionlib_handles", "p36_actionlib_handles.py", duration=8.0, tolerance_s=0.15, stdout=(
        "wait_for_server True",
        "server got goal 1 status _has_header",  # actionlib names status 0 by the first class attribute equal to it
        "server cancel for goal 3 status RECALLING",
        "server cancel for goal 4 status PREEMPTING",
        _P36_GOAL.format(1, ["ACTIVE", "WAITING_FOR_RESULT", "DONE"], "SUCCEEDED", "done", 10),
        _P36_GOAL.format(2, ["PENDING", "WAITING_FOR_RESULT", "DONE"], "REJECTED", "no", 20),
        _P36_GOAL.format(3, ["PENDING", "WAITING_FOR_CANCEL_ACK", "RECALLING", "WAITING_FOR_RESULT", "DONE"],
                         "RECALLED", "canceled", -3),
        _P36_GOAL.format(4, ["ACTIVE", "WAITING_FOR_CANCEL_ACK", "PREEMPTING", "WAITING_FOR_RESULT", "DONE"],
                         "PREEMPTED", "canceled", -4),
        "statuses [('p36-early', 'RECALLED')]",
        "server cancel for goal 5 status PREEMPTING",
        "goal 5 transitions ['ACTIVE', 'PREEMPTING', 'WAITING_FOR_RESULT', 'DONE'] terminal PREEMPTED",
        "statuses after the timeout 0",
        "end",
    )),
]

# A node's own source compiled as Noetic's Python does, whichever Python the grader runs on.
CASES += [
    Case("p37_escape_warnings", "p37_escape_warnings.py", duration=2.0, stdout=(
        "regex 1.25",
        "path ['C:', 'data', 'scans']",
        "octal ['0x1ff']",
    ), stderr_empty=True),
]

CASES_BY_ID = {case.id: case for case in CASES}
