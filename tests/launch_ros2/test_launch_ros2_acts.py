"""A ROS 2 launch file's ros2 command lines as the grader's acts: what each command means, as the CLI reads it."""
from __future__ import annotations

import pytest

from grader.launch.ros2_acts import LaunchActs, cli_act, launch_acts, with_acts
from sim.scenario import ActionGoalSpec, ParamSetSpec, PublicationSpec, Scenario, ServiceCallSpec


def _process(cmd: list[str], shell: bool = False, delay: float = 0.0, after: dict | None = None) -> dict:
    return {"kind": "process", "cmd": cmd, "shell": shell, "delay": delay, "after": after}


def test_service_call_through_a_shell_as_the_substitutions_tutorial_writes_it() -> None:
    act = cli_act(_process(["ros2 service call ", "turtlesim1/spawn ", "turtlesim/srv/Spawn ",
                            '"{x: 2, y: 2, theta: 0.2}"'], shell=True), 0.5)
    assert act == ServiceCallSpec(t=0.5, service="/turtlesim1/spawn", type="turtlesim/srv/Spawn",
                                  request={"x": 2, "y": 2, "theta": 0.2})


def test_param_set_value_is_typed_as_yaml() -> None:
    act = cli_act(_process(["ros2", "param", "set", "/turtlesim1/sim", "background_r", "120"]), 0.0)
    assert act == ParamSetSpec(t=0.0, node="/turtlesim1/sim", name="background_r", value=120)


def test_topic_pub_options() -> None:
    act = cli_act(_process(["ros2", "topic", "pub", "-r", "2", "-w", "1", "/turtle1/cmd_vel",
                            "geometry_msgs/msg/Twist", "{linear: {x: 1.0}}"]), 1.0)
    assert act == PublicationSpec(t=1.0, topic="/turtle1/cmd_vel", type="geometry_msgs/msg/Twist",
                                  values={"linear": {"x": 1.0}}, rate=2.0)
    once = cli_act(_process(["ros2", "topic", "pub", "--once", "/start", "std_msgs/msg/Empty"]), 0.0)
    assert isinstance(once, PublicationSpec) and once.once and once.values == {}


def test_action_send_goal() -> None:
    act = cli_act(_process(["ros2", "action", "send_goal", "/fibonacci", "example_interfaces/action/Fibonacci",
                            "{order: 5}"]), 0.0)
    assert act == ActionGoalSpec(t=0.0, action="/fibonacci", type="example_interfaces/action/Fibonacci",
                                 goal={"order": 5})


@pytest.mark.parametrize("cmd", [["ros2", "run", "turtlesim", "turtlesim_node"], ["rqt"], ["ros2", "bag", "record"]])
def test_other_programs_are_not_acts(cmd: list[str]) -> None:
    assert cli_act(_process(cmd), 0.0) is None


def test_findings_for_commands_that_cannot_be_carried_out_and_for_triggers() -> None:
    processes = [_process(["ros2", "service", "call", "/spawn"]),
                 _process(["ros2", "param", "set", "/sim", "background_r", "{a: 1}"]),
                 _process(["ros2", "service", "call", "/clear", "std_srvs/srv/Empty"], delay=2.0,
                          after={"event": "exit", "process": "ros2-1"}),
                 {"kind": "node", "cmd": ["x"]}]
    acts, findings, handled = launch_acts(processes, "t.launch.py")
    assert handled == {0, 1, 2}
    assert acts.service_calls == [ServiceCallSpec(t=2.0, service="/clear", type="std_srvs/srv/Empty")]
    assert "`ros2 service call` needs a service name and its type" in findings[0]
    assert findings[1].startswith("t.launch.py runs `ros2 param set /sim background_r {a: 1}`, which rosgrade could "
                                  "not carry out")
    assert "runs when ros2-1 exits; rosgrade carries it out at 2 s" in findings[2]


def test_acts_join_the_scenarios_own_in_time_order() -> None:
    scenario = Scenario(robot="turtlesim", service_calls=[ServiceCallSpec(t=3.0, service="/clear",
                                                                          type="std_srvs/srv/Empty")])
    acts = LaunchActs()
    acts.add(ServiceCallSpec(t=1.0, service="/spawn", type="turtlesim/srv/Spawn"))
    merged = with_acts(scenario, acts)
    assert [c.t for c in merged.service_calls] == [1.0, 3.0]
    assert with_acts(scenario, LaunchActs()) is scenario


def test_the_ros2_found_by_find_executable_is_the_ros2_cli() -> None:
    """The substitutions tutorial writes [FindExecutable(name='ros2'), ' service call ', ...]: on a Jazzy machine that
    is /opt/ros/jazzy/bin/ros2, and the grader carries the call out."""
    act = cli_act(_process(["/opt/ros/jazzy/bin/ros2 service call /spawn turtlesim/srv/Spawn '{x: 2, y: 2}'"],
                           shell=True), 0.0)
    assert act == ServiceCallSpec(t=0.0, service="/spawn", type="turtlesim/srv/Spawn", request={"x": 2, "y": 2})
