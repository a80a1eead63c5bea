"""Protocol-level tests: probe nodes run as real processes against the fake grader."""
from __future__ import annotations

import pytest

from tests.nodelib.fake_grader import FakeGrader, float64_msg, frames_as_json, string_msg

START = 1_403_000_000   # the fake grader's default start: deliberately not on a 10 ms clock tick


def test_time_now_zero_then_clock_steps():
    run = FakeGrader("time_now.py").run()
    assert run.returncode == 0, run.output(2)
    lines = run.lines()
    # right after init_node the time is 0, and Time.now() is one cached object
    assert lines[0] == "first 0 True"
    # no /clock yet: it arrives when the node first blocks (or has charged a clock period of calls)
    assert lines[1:4] == ["now 0"] * 3
    # init_node takes 0.1 s (to 1.503); rospy.sleep(0.05) at time 0 first waits for the clock (tick 1.51), then
    # sleeps to 1.56, as rospy does; time.time() moved with sim time from after init_node (1.503)
    name, t_ns, wall_delta = lines[4].split()
    assert int(t_ns) == 1_560_000_000 and abs(int(wall_delta) - 57_000_000) < 1000
    # patched time.sleep wakes at its exact nanosecond deadline
    assert lines[5] == "time_sleep_ns 12300000"
    assert run.output(1).endswith("[INFO] [1700000001.572300, 1.570000]: done 7\n")
    log = run.of("LOG")[0].data
    assert (log["level"], log["msg"], log["name"], log["line"]) == (2, "done 7", "/timeprobe", 16)
    assert run.raw_stdout == b"" and run.raw_stderr == b""


def test_rate_two_publishes_at_start_then_100ms():
    run = FakeGrader("rate_loop.py").run()
    assert run.returncode == 0, run.output(2)
    assert run.lines()[0] == "remaining0 100000000"
    times = [t for t, _ in run.published("/chatter")]
    # init_node ends at 1.503; world time 1.61 twice, then on the 100 ms grid of the clock
    # real rospy's pattern: the first message goes out before the clock, then a Rate created at time 0 sends two
    # at the first tick after its sleep, then every 100 ms (checked against real rospy in tests/conformance)
    assert times == [1_503_000_000, 1_610_000_000, 1_610_000_000, 1_710_000_000, 1_810_000_000]
    advertise = run.of("ADVERTISE")[0].data
    assert advertise == {"id": 1, "topic": "/chatter", "type": "std_msgs/String",
                         "md5sum": "992ce8a1687cec8c8bd883ec73ca41d1", "queue_size": 10, "latch": False}


def test_busy_loop_advances_time_and_ends_at_shutdown():
    run = FakeGrader("busy_shutdown.py", shutdown_ns=1_600_000_000).run()
    assert run.returncode == 0, run.output(2)
    pubs = run.published("/chatter")
    # each iteration is two charged calls (is_shutdown, publish): 5 publishes per 10 ms of sim time
    go = [t for t, body in pubs if body.endswith(b"go")]
    assert go[:4] == [1_503_000_000] * 4 and go[4:9] == [1_513_000_000] * 5 and go[9] == 1_523_000_000
    waits = [f.data["wake_ns"] - f.t_ns for f in run.of("WAIT")[1:]]
    assert set(waits) == {10_000_000}
    # the hook's publish is the last message; the one after the loop is dropped
    assert pubs[-1] == (1_600_000_000, b"\x04\x00\x00\x00stop")
    # the last iteration's publish was interrupted by the shutdown (it yielded first) and dropped
    assert run.lines() == ["hook is_shutdown False", "loops %d 1600000000" % (len(go) + 1)]
    assert run.of("UNREGISTER")[0].t_ns == 1_600_000_000


def test_pure_busy_wait_and_library_busy_wait_see_callbacks():
    messages = [(2_000_000_000, "/value", float64_msg(1.5)), (2_100_000_000, "/value", float64_msg(2.5)),
                (2_200_000_000, "/value", float64_msg(3.5))]
    run = FakeGrader("busy_wait.py", messages=messages).run()
    assert run.returncode == 0, run.output(2)
    assert run.lines() == ["first 1.5 2000000000", "third 3.5 2200000000"]


@pytest.mark.parametrize("mode, returncode", [([], 1), (["catch"], 0)])
def test_shutdown_hooks_and_interrupted_sleep(mode, returncode):
    run = FakeGrader("shutdown_hooks.py", mode, shutdown_ns=1_655_000_000).run()
    assert run.returncode == returncode
    out = run.output()
    # hooks in registration order, with is_shutdown() False; a failing hook is printed and skipped
    assert out.index("first False True") < out.index("boom in hook") < out.index("third False")
    assert "Traceback (most recent call last):" in out
    bodies = [body[4:] for _, body in run.published("/chatter")]
    assert bodies[-1] == b"zero" and b"dropped" not in bodies
    types = [f.data["type"] for f in run.of("EXCEPTION")]
    if returncode == 1:
        assert out.rstrip().endswith("rospy.exceptions.ROSInterruptException: ROS shutdown request")
        assert types == ["RuntimeError", "rospy.exceptions.ROSInterruptException"]
        assert run.of("EXCEPTION")[1].data["frames"][-1]["text"] == "rate.sleep()"
    else:
        assert "caught 'ROS shutdown request' True\nlate hook ran\nsleep after shutdown raised\n" in out
        assert types == ["RuntimeError"]


def test_shutdown_without_init_is_keyboard_interrupt():
    run = FakeGrader("no_init_interrupt.py", shutdown_ns=2_000_000_000).run()
    assert run.returncode == -2
    assert run.output(2).endswith("KeyboardInterrupt\n")
    assert "not reached" not in run.output()


def test_bad_callback_is_logged_and_spin_returns_at_shutdown():
    messages = [(1_600_000_000, "/words", string_msg("a")), (1_700_000_000, "/words", string_msg("b"))]
    run = FakeGrader("bad_callback.py", messages=messages, shutdown_ns=2_000_000_000).run()
    assert run.returncode == 0
    err = run.output(2)
    assert err.startswith("[ERROR] [1700000001.600000, 1.600000]: bad callback: <function bad at 0x")
    assert err.count("ValueError: student bug in callback") == 2 and "callback b\n\n" in err
    assert run.lines() == ["spin returned True"]
    assert [f.data["message"] for f in run.of("EXCEPTION")] == ["student bug in callback a",
                                                                "student bug in callback b"]


def test_two_runs_give_identical_frames():
    messages = [(2_000_000_000, "/value", float64_msg(1.5)), (2_100_000_000, "/value", float64_msg(2.5)),
                (2_200_000_000, "/value", float64_msg(3.5)), (1_600_000_000, "/words", string_msg("a"))]
    for probe in ("busy_wait.py", "busy_shutdown.py", "bad_callback.py"):
        grader = FakeGrader(probe, messages=messages, shutdown_ns=2_500_000_000)
        assert frames_as_json(grader.run()) == frames_as_json(grader.run()), probe


def test_api_errors_params_names_and_wait_for_message_timeout():
    run = FakeGrader("api_errors.py", ["_speed:=0.3", "cmd_vel:=/mobile_base/cmd_vel"]).run()
    assert run.returncode == 0, run.output(2)
    out = run.output()
    assert "before init: ROS node has not been initialized yet. Please call init_node() first\n" in out
    assert "api_errors.py:12: SyntaxWarning: The publisher should be created with an explicit keyword" in out
    assert "TypeError: expected [geometry_msgs/Vector3] but got [std_msgs/String]\n" in out
    assert "TypeError: Invalid number of arguments, args should be ['linear', 'angular'] args are('hello',)" in out
    assert "ROSSerializationException: field linear.x must be float type\n" in out
    assert "params 0.3 True ['" in out and "api_errors.py']\n" in out
    # created before init_node, the publisher was resolved without the remapping (as rospy does)
    assert "names /api / /cmd_vel 1\n" in out
    # 0.5 s after the call at world time 1.403; the clock reads the last tick, 1.90
    assert "wfm: timeout exceeded while waiting for message on topic /nothing 2.0\n" in out
    assert "twice: rospy.init_node() has already been called with different arguments: ('api', [" in out
    assert len(run.published("/cmd_vel")) == 1
