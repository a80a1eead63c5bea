"""In-process tests of rclpy's pure parts: Time/Duration arithmetic, QoS, --ros-args, names, logging filters."""
from __future__ import annotations

import pytest

from tests.nodelib_ros2_rclpy import ros2_grader  # noqa: F401 - puts the ROS 2 import roots on sys.path

import rclpy  # noqa: E402
from rclpy import arguments, names  # noqa: E402
from rclpy.clock import Clock, ClockType, ROSClock  # noqa: E402
from rclpy.duration import Duration, Infinite  # noqa: E402
from rclpy.exceptions import InvalidNodeNameException, NotInitializedException  # noqa: E402
from rclpy.impl.rcutils_logger import RcutilsLogger  # noqa: E402
from rclpy.qos import (DurabilityPolicy, HistoryPolicy, InvalidQoSProfileException, QoSPresetProfiles,  # noqa: E402
                       QoSProfile, ReliabilityPolicy, qos_profile_sensor_data)
from rclpy.time import Time  # noqa: E402


def test_time_minus_time_is_a_duration_and_time_plus_duration_keeps_the_clock_type():
    a = Time(seconds=2, nanoseconds=5, clock_type=ClockType.ROS_TIME)
    b = Time(seconds=1.5, clock_type=ClockType.ROS_TIME)
    assert a - b == Duration(nanoseconds=500_000_005)
    assert (b + Duration(seconds=1)).clock_type is ClockType.ROS_TIME
    assert repr(b - Duration(seconds=1)) == "Time(nanoseconds=500000000, clock_type=ROS_TIME)"
    assert b - a == Duration(nanoseconds=-500_000_005)   # durations may be negative


def test_time_errors_match_rclpy():
    with pytest.raises(TypeError, match="Can't compare times with different clock types"):
        Time(clock_type=ClockType.ROS_TIME) < Time()
    with pytest.raises(ValueError, match="Seconds value must not be negative"):
        Time(seconds=-1)
    with pytest.raises(ValueError, match="Subtraction leads to negative time."):
        Time(seconds=1) - Duration(seconds=2)
    with pytest.raises(TypeError, match="Clock type must be a ClockType enum"):
        Time(clock_type=1)


def test_seconds_nanoseconds_and_messages():
    t = Time(seconds=3, nanoseconds=250, clock_type=ClockType.ROS_TIME)
    assert t.seconds_nanoseconds() == (3, 250)
    msg = t.to_msg()
    assert (msg.sec, msg.nanosec) == (3, 250)
    assert Time.from_msg(msg) == t
    assert Duration.from_msg(Duration(seconds=-1.5).to_msg()) == Duration(seconds=-1.5)


def test_duration_arithmetic_and_infinite():
    """Jazzy's Duration compares but has no arithmetic of its own (Kilted added +, - and *)."""
    assert str(Infinite) == "Infinite" and str(Duration(nanoseconds=3)) == "3 nanoseconds"
    assert Duration(seconds=1) > Duration(nanoseconds=999_999_999)
    with pytest.raises(TypeError, match=r"unsupported operand type\(s\) for \*: 'Duration' and 'int'"):
        Duration(seconds=1) * 2
    with pytest.raises(TypeError, match=r"unsupported operand type\(s\) for \+: 'Duration' and 'Duration'"):
        Duration(seconds=1) + Duration(seconds=2)


def test_clock_types_and_ros_clock():
    assert isinstance(Clock(clock_type=ClockType.ROS_TIME), ROSClock)
    assert repr(ROSClock()) == "Clock(clock_type=ROS_TIME)"
    assert Clock().now().clock_type is ClockType.SYSTEM_TIME


def test_qos_profiles():
    assert QoSProfile(depth=7).history == HistoryPolicy.KEEP_LAST
    assert qos_profile_sensor_data.reliability == ReliabilityPolicy.BEST_EFFORT and qos_profile_sensor_data.depth == 5
    assert QoSPresetProfiles.SENSOR_DATA.value == qos_profile_sensor_data
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    assert latched.keeps() == 1 and QoSProfile(history=HistoryPolicy.KEEP_ALL).keeps() is None
    with pytest.raises(InvalidQoSProfileException):
        QoSProfile()


def test_ros_args_parameters_remaps_and_non_ros_args():
    parsed = arguments.parse(["x.py", "0.3", "--ros-args", "-p", "use_sim_time:=true", "-p", "speed:=1",
                              "-p", "mover:gain:=0.5", "-r", "cmd_vel:=/robot/cmd_vel", "-r", "__node:=renamed",
                              "--log-level", "debug", "--", "tail"])
    assert parsed.non_ros == ["x.py", "0.3", "tail"]
    assert parsed.params == {("", "use_sim_time"): True, ("", "speed"): 1, ("mover", "gain"): 0.5}
    assert ("", "cmd_vel", "/robot/cmd_vel") in parsed.remaps and parsed.log_levels == {"": 10}
    assert rclpy.utilities.remove_ros_args(["a", "--ros-args", "-p", "x:=1"]) == ["a"]


@pytest.mark.parametrize("text,value", [("true", True), ("False", False), ("3", 3), ("2.5", 2.5), ("1e3", 1000.0),
                                        ("'007'", "007"), ("[1, 2]", [1, 2]), ("hello", "hello")])
def test_parameter_values_read_as_yaml(text, value):
    assert arguments.parse_scalar(text) == value and type(arguments.parse_scalar(text)) is type(value)


def test_names_expand_and_validate():
    assert names.expand_topic_name("cmd_vel", "mover", "/robot") == "/robot/cmd_vel"
    assert names.expand_topic_name("~/odom", "mover", "/") == "/mover/odom"
    assert names.logger_name("mover", "/robot/a") == "robot.a.mover"
    with pytest.raises(InvalidNodeNameException, match="node name must not contain characters"):
        names.validate_node_name("my-node")


def test_not_initialized_text():
    assert str(NotInitializedException("cannot create node")) == \
        "rclpy.init() has not been called. msg:cannot create node"


def test_throttle_once_skip_first_are_per_call_site(capsys):
    logger = RcutilsLogger("unit")
    results = [logger.info("a", once=True) for _ in range(3)]
    assert results == [True, False, False]
    results = [logger.info("b", skip_first=True) for _ in range(3)]
    assert results == [False, True, True]
    assert capsys.readouterr().err.count("[INFO] [") == 3
    with pytest.raises(TypeError, match="not one of the recognized logging options"):
        logger.info("c", throttle=1)


def test_tf_transformations_is_ros1_math():
    import tf_transformations as tft
    q = tft.quaternion_from_euler(0.0, 0.0, 1.0)
    assert abs(tft.euler_from_quaternion(q)[2] - 1.0) < 1e-12
    assert tft.quaternion_from_euler.__module__ == "rosgrade_transformations"


def test_clock_type_text_is_jazzys_int_enums():
    assert str(ClockType.ROS_TIME) == f"{ClockType.ROS_TIME}" == "1" and f"{ClockType.ROS_TIME:d}" == "1"
    assert repr(ClockType.SYSTEM_TIME) == "<ClockType.SYSTEM_TIME: 2>" and ClockType.ROS_TIME == 1


def test_log_of_a_non_str_is_pybind11s_type_error():
    with pytest.raises(TypeError) as info:
        RcutilsLogger("unit").info(123)
    assert ("1. (arg0: typing.SupportsInt, arg1: str, arg2: str, arg3: str, arg4: str, arg5: typing.SupportsInt) "
            "-> None\n\nInvoked with: <LoggingSeverity.INFO: 20>, 'unit', 123, ") in str(info.value)


def test_dds_type_names():
    from rclpy._graph import dds_type_name
    assert dds_type_name("geometry_msgs/msg/Twist") == "geometry_msgs::msg::dds_::Twist_"
    assert dds_type_name("std_srvs/srv/Empty_Request") == "std_srvs::srv::dds_::Empty_Request_"


@pytest.mark.parametrize("callback, with_info", [
    (lambda msg: None, False),
    (lambda msg, name="scan": None, False),  # a loop's `lambda msg, n=name: ...`: the message alone, as rclpy 7.1
    (lambda msg, info: None, True),
    (lambda *args: None, False),
])
def test_a_subscription_callback_gets_the_message_info_only_when_one_argument_does_not_bind(callback,
                                                                                        with_info: bool) -> None:
    from rclpy.subscription import _wants_info

    assert _wants_info(callback) is with_info


def test_a_callback_that_takes_no_message_is_refused() -> None:
    from rclpy.subscription import _wants_info

    with pytest.raises(TypeError):
        _wants_info(lambda: None)
