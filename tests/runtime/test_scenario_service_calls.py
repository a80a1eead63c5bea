"""The grader as a caller: a scenario's service_calls go out at their times as `ros2 service call` would make them,
one after the other, waiting for a service that is not offered yet; the world's services are called the same way."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from grader.metrics.run import service_calls
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import RunError, run
from sim import Scenario

pytestmark = pytest.mark.slow

NODES = Path(__file__).resolve().parent / "nodes" / "services"
ADD = "example_interfaces/srv/AddTwoInts"


def _calls(*times: float) -> list[dict]:
    return [{"t": t, "service": "/add_two_ints", "type": ADD, "request": {"a": i, "b": 10}}
            for i, t in enumerate(times)]


def test_calls_wait_for_a_service_offered_late_then_follow_one_another(tmp_path) -> None:
    scenario = Scenario(duration=3.0, service_calls=_calls(0.2, 0.3, 2.5))
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=NODES / "late_server.py", flavour="ros2"),)),
        tmp_path / "late.mcap", tmp_path / "late.log")
    calls = service_calls(Recording.open(tmp_path / "late.mcap"))
    # the server offers /add_two_ints after rclpy.init (0.35 s) and its 1 s sleep: the first two calls go out then
    assert [(round(c.t, 3), c.request["a"], c.response) for c in calls] == [
        (3.35, 0, {"sum": 10}), (3.35, 1, {"sum": 11}), (4.5, 2, {"sum": 12})]


def test_a_call_to_a_service_never_offered_is_never_made(tmp_path) -> None:
    scenario = Scenario(duration=1.0, service_calls=_calls(0.2))
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=NODES / "add_client.py", flavour="ros2"),)),
        tmp_path / "none.mcap", tmp_path / "none.log")
    assert service_calls(Recording.open(tmp_path / "none.mcap")) == ()


def test_the_worlds_services_are_called_through_the_same_routing(tmp_path) -> None:
    spawn = {"t": 0.5, "service": "/spawn", "type": "turtlesim/Spawn",
             "request": {"x": 2.0, "y": 3.0, "theta": 0.0, "name": "leo"}}
    scenario = Scenario(robot="turtlesim", duration=1.0, service_calls=[spawn])
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=NODES / "rospy_client.py"),)),
        tmp_path / "spawn.mcap", tmp_path / "spawn.log")
    recording = Recording.open(tmp_path / "spawn.mcap")
    assert [(round(c.t, 3), c.response) for c in service_calls(recording)] == [(2.5, {"name": "leo"})]
    topics = {(i.topic, i.callerid, i.origin) for i in recording.topics()}
    assert ("/rosgrade/service/spawn/request", "/rosgrade", "grader") in topics
    assert ("/rosgrade/service/spawn/response", "/turtlesim", "world") in topics
    assert any(topic == "/leo/pose" for topic, _, _ in topics)


def test_a_call_goes_out_at_its_time_while_the_world_runs_ahead_of_a_busy_server(tmp_path) -> None:
    scenario = Scenario(duration=2.0, service_calls=_calls(0.555, 1.234))
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=NODES / "busy_server.py", flavour="ros2"),)),
        tmp_path / "busy.mcap", tmp_path / "busy.log")
    calls = service_calls(Recording.open(tmp_path / "busy.mcap"))
    assert [(round(c.t, 6), c.response) for c in calls] == [(2.555, {"sum": 10}), (3.234, {"sum": 11})]


@pytest.mark.parametrize("call, says", [
    ({"type": ADD, "request": {"a": 1, "c": 2}}, "service_calls[0] to /add_two_ints: {'a': 1, 'c': 2} is not a "
                                                 "request of example_interfaces/srv/AddTwoInts"),
    ({"type": "nope/srv/Nope", "request": {}}, "unknown message type 'nope/srv/Nope_Request'"),
])
def test_a_call_the_scenario_cannot_make_stops_the_run_before_it_starts(tmp_path, call: dict, says: str) -> None:
    scenario = Scenario(duration=1.0, service_calls=[{"t": 0.5, "service": "/add_two_ints", **call}])
    with pytest.raises(RunError, match=re.escape(says)):
        run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=NODES / "add_server.py", flavour="ros2"),)),
            tmp_path / "bad.mcap", tmp_path / "bad.log")
    assert not (tmp_path / "bad.mcap").exists()
