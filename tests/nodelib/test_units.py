"""In-process unit tests of rospy's pure logic: Rate on a fake clock, names and remapping, logging, parameters."""
from __future__ import annotations

import sys

import pytest

from grader.nodelib import import_roots

sys.path[:0] = [str(p) for p in import_roots("ros1")]
import rospy  # noqa: E402
from rospy import core, names, params, rostime, timer  # noqa: E402


class FakeClock:
    """ROS time in ns that only moves when rospy.sleep is called (rounded up to the 10 ms /clock grid)."""

    def __init__(self, t_ns: int) -> None:
        self.t_ns = t_ns
        self.sleeps: list[int] = []

    def now(self) -> rospy.Time:
        return rospy.Time(self.t_ns // 10**9, self.t_ns % 10**9)

    def sleep(self, duration) -> None:
        d = duration.to_nsec()
        self.sleeps.append(d)
        if d > 0:
            self.t_ns = -(-(self.t_ns + d) // 10_000_000) * 10_000_000


@pytest.fixture
def clock(monkeypatch):
    fake = FakeClock(0)
    monkeypatch.setattr(rostime, "_now", fake.now)
    monkeypatch.setattr(timer, "sleep", fake.sleep)
    return fake


def test_rate_created_at_time_zero_returns_at_once_then_resets(clock):
    rate = rospy.Rate(10)
    assert repr(rate.remaining()) == "rospy.Duration[100000000]"
    clock.t_ns = 100_507_000_000
    rate.sleep()                       # far behind: returns immediately, anchor reset to now
    assert clock.sleeps == [100_000_000 - 100_507_000_000]
    starts = []
    for _ in range(10):
        starts.append(clock.t_ns)
        rate.sleep()
    # no drift, the first wake on the tick grid: the reference's observed 100.507 -> 101.510
    assert starts[0] == 100_507_000_000 and clock.t_ns == 101_510_000_000


def test_rate_catches_up_then_resets_after_two_periods(clock):
    clock.t_ns = 10_000_000_000
    rate = rospy.Rate(10)
    remaining = []
    for _ in range(4):
        clock.t_ns += 250_000_000       # a loop body of 2.5 periods
        remaining.append(rate.remaining().to_nsec())
        rate.sleep()
    # behind by 1.5 periods: catch up (anchor += period); behind by 3: reset the anchor to the sleep's start
    assert remaining == [-150_000_000, -300_000_000, -150_000_000, -300_000_000]
    assert int(1e9 / 3) == rospy.Rate(3).sleep_dur.to_nsec()
    with pytest.raises(ZeroDivisionError):
        rospy.Rate(0)
    with pytest.raises(TypeError):
        rospy.Rate("10")


def test_names_resolution_and_remapping(monkeypatch):
    argv = ["c3.py", "0.2", "cmd_vel:=/mobile_base/cmd_vel", "_speed:=0.3", "__name:=renamed", "a:=b:=c"]
    assert names.myargv(argv) == ["c3.py", "0.2"]
    mappings = names.load_mappings(argv)
    assert mappings == {"cmd_vel": "/mobile_base/cmd_vel", "__name": "renamed"}
    assert names.resolve_in("~odom", "/robot1/c3") == "/robot1/c3/odom"
    assert names.resolve_in("cmd_vel", "/robot1/c3") == "/robot1/cmd_vel"
    assert names.resolve_in("/cmd_vel//", "/robot1/c3") == "/cmd_vel"
    assert names.namespace("/robot1/c3") == "/robot1/" and names.make_global_ns("robot1") == "/robot1/"
    monkeypatch.setattr(names, "_mappings", mappings)
    names.initialize_mappings("/c3")
    remaps = names.get_resolved_mappings()
    assert names.resolve_in("cmd_vel", "/c3", remaps) == "/mobile_base/cmd_vel"
    assert names.resolve_in("/cmd_vel", "/c3", remaps) == "/mobile_base/cmd_vel"
    names.initialize_mappings("/robot1/c3")      # in a namespace only the relative name is remapped
    remaps = names.get_resolved_mappings()
    assert names.resolve_in("/cmd_vel", "/robot1/c3", remaps) == "/cmd_vel"
    names.initialize_mappings("/unnamed")
    assert names.is_legal_base_name("mover") and not names.is_legal_base_name("my-node")


def test_log_format_and_arguments():
    assert core.format_line(core.WARN, "x", 1795250908.5231134, 21.06) == \
        "[WARN] [1795250908.523113, 21.060000]: x\n"
    # during init_node, before rospy has set up its clock, the line carries the wall time only
    assert core.format_line(core.INFO, "x", 1795435121.856229, None) == "[INFO] [1795435121.856229]: x\n"
    assert core.format_message("x=%.2f y=%.2f", (1.23456, 2.0)) == "x=1.23 y=2.00"
    assert core.format_message("pct-args tuple %s", ((1, 2),)) == "pct-args tuple (1, 2)"
    assert core.format_message("literal 100% no args", ()) == "literal 100% no args"
    assert core.format_message("dict arg %(a)s", ({"a": 5},)) == "dict arg 5"
    with pytest.raises(TypeError, match="a real number is required, not str"):
        core.format_message("bad format %d", ("notanumber",))


def test_throttle_keys_strict_and_per_call_site(monkeypatch):
    now = {"ns": 0}
    monkeypatch.setattr(rostime, "_now", lambda: rospy.Time(0, now["ns"]))
    emitted = []
    monkeypatch.setattr(core, "_emit", lambda level, msg, args, frame: emitted.append(format(msg) % args))
    monkeypatch.setattr(core, "_throttle_last", {})

    def helper(i):
        rospy.loginfo_throttle(0.5, "via helper %d", i)

    for i in range(21):                  # a 0.1 s loop: strict '>' prints every 6th iteration
        now["ns"] = i * 100_000_000
        rospy.loginfo_throttle(0.5, "A%d", i); rospy.loginfo_throttle(0.5, "B%d", i)  # noqa: E702
        helper(i)
        rospy.logwarn_once("once")
    assert [m for m in emitted if m.startswith("A")] == ["A0", "A6", "A12", "A18"]
    assert [m for m in emitted if m.startswith("B")] == ["B0", "B6", "B12", "B18"]
    assert [m for m in emitted if m.startswith("via")] == ["via helper 0", "via helper 6", "via helper 12",
                                                            "via helper 18"]
    assert emitted.count("once") == 1


def test_param_scalars_and_tree():
    assert [params.parse_scalar(v) for v in ("0.3", "3", "true", "Off", "~", "'x'", "1e3", "[1, 2]", "abc")] == \
        [0.3, 3, True, False, None, "x", "1e3", [1, 2], "abc"]
    params.set_param("/robot/speed", 0.3)
    params.set_param("/robot/name", "tb3")
    assert params.get_param("/robot") == {"speed": 0.3, "name": "tb3"}
    assert params.has_param("/robot/speed") and "/robot/name" in params.get_param_names()
    params.delete_param("/robot/speed")
    with pytest.raises(KeyError, match="'/robot/speed'"):
        params.get_param("/robot/speed")
    assert params.get_param("/robot/speed", 1.0) == 1.0
    assert params.search_param("robot") == "/robot"


def test_exceptions_and_init_errors():
    assert rospy.ROSInterruptException.__mro__[1:] == (rospy.ROSException, Exception, KeyboardInterrupt,
                                                      BaseException, object)
    assert str(rospy.ROSTimeMovedBackwardsException(1.5)) == "ROS time moved backwards"
    with pytest.raises(rospy.ROSInitException, match=r"time is not initialized. Have you called init_node\(\)\?"):
        rospy.Time.now()
    with pytest.raises(ValueError, match="namespaces are not allowed in node names"):
        rospy.init_node("/my_node")
    with pytest.raises(ValueError, match="name must not be empty"):
        rospy.init_node("")
    with pytest.raises(TypeError, match=r"shutdown hook \[None\] must be a function or callable object: "
                                        r"<class 'NoneType'>"):
        rospy.on_shutdown(None)
    assert rospy.get_name() == "/unnamed"
    assert repr(rospy.Time(5, 2500)) == "rospy.Time[5000002500]" and str(rospy.Time(1, 500000000)) == "1500000000"
    assert type(rospy.Time(10) - rospy.Time(8, 5)).__name__ == "Duration"
    assert type(rospy.Time(10) + rospy.Duration(1.5)) is rospy.Time


def test_every_client_library_s_frames_count_as_library_code():
    """The CPU-time tick and Ctrl+C act only in student code: rospy's, rclpy's and the runtime's own frames are
    library frames (a tick that yielded inside rospy, holding one of its locks, could hang the node)."""
    from rosgrade_node import scheduler

    from grader.nodelib import NODELIB, import_roots

    assert str(NODELIB) + "/" in scheduler._LIBRARY_DIRS
    for root in (*import_roots("ros1"), *import_roots("ros2")):
        assert str(root / "x.py").startswith(scheduler._LIBRARY_DIRS)
    assert rospy.__file__.startswith(scheduler._LIBRARY_DIRS)
    assert not str(NODELIB.parents[1] / "reference_solutions" / "move_circle.py").startswith(scheduler._LIBRARY_DIRS)


def test_a_log_call_site_is_keyed_by_the_file_inspect_names():
    """The throttle/once key is built without importing inspect, but names the file as inspect.getabsfile does."""
    import inspect

    frame = sys._getframe()
    assert core._call_site(frame)[0] == inspect.getabsfile(frame)
