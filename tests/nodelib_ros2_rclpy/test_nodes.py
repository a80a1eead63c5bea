"""rclpy probes run against the stand-in grader: frames, sim-time timers, Ctrl+C in both signal modes, logging."""
from __future__ import annotations

import math

import pytest

from tests.nodelib_ros2_rclpy.ros2_grader import SIM, Ros2Grader, cdr, decode

import rosgrade_rosidl  # noqa: E402

# By name, not by package import: this process also holds the ROS 1 packages of the same names.
TransformStamped = rosgrade_rosidl.message_class("geometry_msgs/msg/TransformStamped")
TwistStamped = rosgrade_rosidl.message_class("geometry_msgs/msg/TwistStamped")
Odometry = rosgrade_rosidl.message_class("nav_msgs/msg/Odometry")
TFMessage = rosgrade_rosidl.message_class("tf2_msgs/msg/TFMessage")

RCL_ERROR = ("rclpy._rclpy_pybind11.RCLError: Failed to publish: publisher's context is invalid, at "
             "/project/src/rcl/publisher.c:423")


def _odom(x: float) -> bytes:
    msg = Odometry()
    msg.pose.pose.position.x = x
    return cdr(msg)


def circle(mode: str):
    return Ros2Grader("circle_node.py", args=[mode, *SIM], end_ns=4_000_000_000, shutdown_ns=3_000_000_000,
                      messages=[(2_000_000_000, "/odom", _odom(1.5))]).run()


@pytest.fixture(scope="module")
def default_run():
    return circle("default")


@pytest.fixture(scope="module")
def no_run():
    return circle("no")


def test_init_and_endpoints_are_announced_with_ros2_types(default_run):
    init = default_run.of("INIT")[0].data
    assert init == {"name": "/move_circle", "anonymous": False, "log_level": 20, "disable_signals": False}
    advertised = {f.data["topic"]: f.data for f in default_run.of("ADVERTISE")}
    # Every rclpy node publishes its parameter changes, as real rclpy's do.
    assert advertised["/parameter_events"]["type"] == "rcl_interfaces/msg/ParameterEvent"
    adv = advertised["/cmd_vel"]
    assert adv["type"] == "geometry_msgs/msg/TwistStamped"
    assert adv["md5sum"].startswith("RIHS01_") and adv["queue_size"] == 10 and adv["latch"] is False
    sub = default_run.of("SUBSCRIBE")[0].data
    assert (sub["topic"], sub["type"]) == ("/odom", "nav_msgs/msg/Odometry")


def test_timer_fires_overdue_once_at_first_clock_then_on_its_grid(default_run):
    # The node starts at 1.403 s and rclpy.init returns 0.35 s later (rclpy.context.STARTUP_NS): first /clock 1.76.
    times = [t for t, _ in default_run.published("/cmd_vel")]
    assert times[:4] == [1_760_000_000, 1_800_000_000, 1_900_000_000, 2_000_000_000]
    stamps = [decode(TwistStamped, data).header.stamp for _, data in default_run.published("/cmd_vel")]
    assert (stamps[0].sec, stamps[0].nanosec) == (1, 760_000_000)


def test_now_is_zero_before_the_first_spin(default_run):
    assert "init now=Time(nanoseconds=0, clock_type=ROS_TIME)" in default_run.output(2)


def test_subscription_callback_sees_the_message_and_the_clock(default_run):
    assert "odom x=1.50 now=2000000000" in default_run.lines()


def test_default_handlers_shut_the_context_down_before_except(default_run):
    lines = default_run.lines()
    assert "CAUGHT KeyboardInterrupt() ok=False" in lines
    assert "PUBLISH in except: " + RCL_ERROR in lines
    assert all(t < 3_000_000_000 for t, _ in default_run.published("/cmd_vel"))
    err = default_run.output(2)
    assert "[move_circle]: Stopping the robot...\nFailed to publish log message to rosout: publisher's context is " \
           "invalid, at /project/src/rcl/publisher.c:423\n" in err
    assert default_run.returncode == 0 and lines[-1] == "done"


def test_signal_handler_options_no_keeps_the_context_and_delivers_the_stop(no_run):
    assert "CAUGHT KeyboardInterrupt() ok=True" in no_run.lines() and "PUBLISH in except: ok" in no_run.lines()
    last_time, last = no_run.published("/cmd_vel")[-1]
    assert last_time == 3_000_000_000 and decode(TwistStamped, last).twist.linear.x == 0.0
    assert no_run.of("INIT")[0].data["disable_signals"] is True
    assert any(f.data["msg"] == "Stopping the robot..." for f in no_run.of("LOG"))


def test_log_lines_are_rcutils_format_on_stderr_with_wall_stamp_and_log_frames(default_run):
    first = default_run.output(2).splitlines()[0]
    # logged right after rclpy.init, which returns 0.35 s after the start at 1.403 s (rclpy.context.STARTUP_NS)
    assert first == "[INFO] [1700000001.753000000] [move_circle]: init now=Time(nanoseconds=0, clock_type=ROS_TIME)"
    log = default_run.of("LOG")[0].data
    assert (log["level"], log["name"], log["function"]) == (20, "move_circle", "__init__")
    assert log["file"].endswith("circle_node.py")


def test_throttle_uses_the_wall_clock_and_takes_the_next_tick_after_a_second(default_run):
    ticks = [line for line in default_run.output(2).splitlines() if "] [move_circle]: tick" in line]
    assert ticks == ["[INFO] [1700000001.760000000] [move_circle]: tick 1",
                     "[INFO] [1700000002.800000000] [move_circle]: tick 12"]


def test_uncaught_keyboard_interrupt_dies_by_sigint():
    run = Ros2Grader("uncaught_probe.py", args=list(SIM), end_ns=3_000_000_000, shutdown_ns=2_000_000_000).run()
    assert run.returncode == -2
    assert run.output(2).rstrip().endswith("KeyboardInterrupt")


@pytest.fixture(scope="module")
def api_run():
    return Ros2Grader("api_probe.py", args=list(SIM), end_ns=6_000_000_000).run()


@pytest.mark.parametrize("line", [
    "node before init: rclpy.exceptions.NotInitializedException: rclpy.init() has not been called. "
    "msg:cannot create node",
    "now before spin: Time(nanoseconds=0, clock_type=ROS_TIME)",
    "declare int into double: rclpy.exceptions.InvalidParameterTypeException: Trying to set parameter 'speed' to "
    "'2' of type 'INTEGER', expecting type 'DOUBLE': speed",
    "declare radius: 0.5",
    "use_sim_time: True",
    "undeclared: rclpy.exceptions.ParameterNotDeclaredException: Invalid access to undeclared parameter(s): nope",
    "set wrong type: False",
    "publish wrong type: builtins.TypeError: Expected <class 'geometry_msgs.msg._twist_stamped.TwistStamped'>, "
    "got <class 'geometry_msgs.msg._twist.Twist'>",
    "bad qos: builtins.TypeError: Expected QoSProfile or int, but received <class 'str'>",
    # The stand-in grader connects an endpoint at its first BATCH, and the node's parameter services and events
    # charge a clock period of call quanta before the count: one BATCH comes between (the session's discovery is
    # conformance probe p20's).
    "subscription count: 1",
    "fqn: ('api', '/', '/api')",
    "spin_once(0) waited 0.0",
    "duration: builtins.TypeError: unsupported operand type(s) for +: 'Duration' and 'Duration'",  # Jazzy's
    "publish after destroy: rclpy._rclpy_pybind11.InvalidHandle: cannot use Destroyable because destruction was "
    "requested",
    "ok after shutdown: False",
    "shutdown twice: builtins.RuntimeError: Context must be initialized before it can be shutdown",
])
def test_api_behaviour(api_run, line):
    assert line in api_run.lines()


def test_spin_once_counts_each_clock_update_as_work(api_run):
    # four spin_once: /clock 1.77 (the first after rclpy.init's 0.35 s and the 10 ms of calls the node's parameter
    # services and declarations charge), the overdue 0.5 s timer, /clock 1.78, 1.79
    assert "ticks [1770000000]" in api_run.lines()


def test_logging_filters_levels_and_deprecated_warn(api_run):
    err = api_run.output(2)
    assert "once 0" in err and "once 1" not in err
    assert "skip 0" not in err and "skip 1" in err and "skip 2" in err
    assert "hidden debug" not in err
    assert "DeprecationWarning" not in err  # Jazzy's warn() is deprecated in its docstring only
    assert "[WARN] [" in err and "[api]: old warn" in err


def test_transient_local_publisher_registers_latched(api_run):
    adv = [f.data for f in api_run.of("ADVERTISE") if f.data["topic"] == "/status"]
    assert adv[0]["latch"] is True and adv[0]["queue_size"] == 1
    # destroy_node unregisters every publisher and the parameter services.
    registered = [f.data["id"] for f in api_run.of("ADVERTISE")] + [f.data["id"] for f in api_run.of("SERVE")]
    assert sorted(f.data["id"] for f in api_run.of("UNREGISTER")) == sorted(registered)


def test_blocking_callback_starves_subscriptions_and_the_clock():
    # 0.35 s later than the node's start would have it without rclpy.init's start-up (rclpy.context.STARTUP_NS)
    run = Ros2Grader("starve_probe.py", args=list(SIM), end_ns=3_350_000_000, shutdown_ns=2_850_000_000,
                     messages=[(1_950_000_000 + i * 50_000_000, "/odom", _odom(0.0)) for i in range(10)]).run()
    waits = [line for line in run.lines() if line.startswith("waiting")]
    assert len(waits) >= 10 and set(waits) == {"waiting odoms=0 clock_moved=False"}
    assert run.lines()[-1] == "interrupted in sleep"


def test_tf2_listener_fills_the_buffer_while_spinning():
    msgs = []
    for i in range(10):
        t = TransformStamped()
        t.header.frame_id, t.child_frame_id = "odom", "base_footprint"
        t.header.stamp.sec, t.header.stamp.nanosec = 1, 500_000_000 + i * 50_000_000
        t.transform.translation.x = 0.1 * i
        t.transform.rotation.z, t.transform.rotation.w = math.sin(0.1), math.cos(0.1)
        msgs.append((1_500_000_000 + i * 50_000_000, "/tf", cdr(TFMessage(transforms=[t]))))
    run = Ros2Grader("tf_probe.py", args=list(SIM), end_ns=3_000_000_000, messages=msgs).run()
    assert run.lines() == ['before: "odom" passed to lookupTransform argument target_frame does not exist. ',
                           "after: x=0.900 yaw=0.200 stamp=1"]


def test_runs_are_deterministic():
    from tests.nodelib.fake_grader import frames_as_json
    assert frames_as_json(circle("default")) == frames_as_json(circle("default"))


@pytest.fixture(scope="module")
def edge_run():
    return Ros2Grader("edge_probe.py", args=list(SIM), end_ns=6_000_000_000).run()


def test_sleep_for_on_sim_time_wakes_at_the_tick_a_spinning_thread_applies(edge_run):
    # the spinner would otherwise sleep until the end of the run (no timer, no message wakes it)
    assert "sleep_for True 300000000" in edge_run.lines()


def test_clock_type_prints_as_jazzys_int_enum(edge_run):
    assert "clock type 1 1" in edge_run.lines()


@pytest.mark.parametrize("line", [
    "second type publisher: rclpy._rclpy_pybind11.RCLError: Failed to create publisher: create_publisher() called "
    "for existing topic name rt/cmd_vel with incompatible type geometry_msgs::msg::dds_::Twist_, at "
    "/project/src/publisher.cpp:145, at /project/src/rcl/publisher.c:117",
    "second type subscription: rclpy._rclpy_pybind11.RCLError: Failed to create subscription: invalid allocator, at "
    "/project/src/rcl/subscription.c:261",
    "same type again: '/cmd_vel'",
    "other type once the topic is free: '/cmd_vel'",
])
def test_one_type_per_topic_in_a_context(edge_run, line):
    assert line in edge_run.lines()


@pytest.mark.parametrize("topic", ["rosout", "clock"])
def test_the_nodes_own_topics_take_their_type(edge_run, topic):
    assert any(line.startswith(f"String on /{topic}: ") and f"topic name rt/{topic} with incompatible type "
               "std_msgs::msg::dds_::String_" in line for line in edge_run.lines())


@pytest.mark.parametrize("line", [
    "int type: builtins.AttributeError: type object 'type' has no attribute '_TYPE_SUPPORT' This might be a ROS 1 "
    "message type but it should be a ROS 2 message type. Make sure to source your ROS 2 workspace after your ROS 1 "
    "workspace.",
    "service as message: builtins.RuntimeError: The message type provided is not valid "
    "(<class 'std_srvs.srv._empty.Empty'>), this might be a service or action",
    "message as service: builtins.RuntimeError: The service type provided is not valid "
    "(<class 'std_msgs.msg._string.String'>), this might be a message or action",
])
def test_classes_without_type_support_fail_as_in_rclpy(edge_run, line):
    assert line in edge_run.lines()


def test_bad_node_name_warns_once_about_the_rosout_publisher(edge_run):
    err = edge_run.output(2)
    warning = ("RuntimeWarning: Failed to fini rosout publisher: rcl node implementation is invalid, at "
               "/project/src/rcl/node.c:390")
    assert err.count(warning) == 1 and "node.py:" in err.split(warning)[0]


def test_create_timer_after_shutdown_is_an_rcl_error_of_the_context(edge_run):
    assert edge_run.lines()[-1] == (
        "timer after shutdown: rclpy._rclpy_pybind11.RCLError: failed to create timer: the given context is not "
        "valid, either rcl_init() was not called or rcl_shutdown() was called., at "
        "/project/src/rcl/guard_condition.c:67")
