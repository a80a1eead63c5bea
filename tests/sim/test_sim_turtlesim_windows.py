"""Two turtlesim windows in one world (a launch file that starts turtlesim_node twice): the second lives under its
node's namespace, answers its own services and parameters, publishes under its node's name, and the merged samples
come in time order, the first window's first at one time."""
from __future__ import annotations

import pytest

from sim import open_world
from sim.scenario import Scenario, ScriptedCommand, TurtlesimWindow
from sim.turtlesim import TurtlesimError, TurtlesimWorld
from sim.turtlesim_windows import TurtlesimWindows


class Tree(dict):
    def has(self, name: str) -> bool:
        return name in self

    def set(self, name: str, value: object) -> None:
        self[name] = value


def _world(flavour: str = "ros2") -> tuple[TurtlesimWindows, Tree]:
    scenario = Scenario(robot="turtlesim", duration=2.0, script=[ScriptedCommand(t=0.0, linear=1.0)],
                        turtlesim_windows=[TurtlesimWindow(node="/turtlesim2/sim", params={"background_g": 7})])
    world = open_world(scenario, flavour)
    tree = Tree()
    world.use_parameters(tree)
    return world, tree


def test_one_window_is_the_plain_world() -> None:
    assert type(open_world(Scenario(robot="turtlesim"))) is TurtlesimWorld


@pytest.mark.parametrize("flavour", ["ros1", "ros2"])
def test_the_second_window_lives_under_its_nodes_namespace(flavour: str) -> None:
    world, tree = _world(flavour)
    assert world.command_topics == ("/turtle1/cmd_vel", "/turtlesim2/turtle1/cmd_vel")
    assert "/turtlesim2/spawn" in {s.name for s in world.services}
    assert tree["/turtlesim2/sim/background_g"] == 7 and tree["/turtlesim/background_g"] == 86
    second = {t.topic: t.node for t in world.publications if t.topic.startswith("/turtlesim2/")}
    assert second == {"/turtlesim2/turtle1/pose": "/turtlesim2/sim",
                      "/turtlesim2/turtle1/color_sensor": "/turtlesim2/sim"}
    assert "/ground_truth/odom" in {t.topic for t in world.publications}  # the first window's only


def test_the_script_drives_the_first_window_and_a_command_the_second() -> None:
    world, _ = _world()
    assert world.command("/turtlesim2/turtle1/cmd_vel", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0))
    samples = world.advance_to(world.start_ns + 200_000_000)
    assert [s.t_ns for s in samples] == sorted(s.t_ns for s in samples)
    tick = next(s.t_ns for s in samples if s.topic == "/turtle1/pose")
    first_tick = [s.topic for s in samples if s.t_ns == tick]
    assert first_tick.index("/turtle1/pose") < first_tick.index("/turtlesim2/turtle1/pose")
    first, second = world.windows
    assert first.turtles["turtle1"].x > second.turtles["turtle1"].x  # the script drove turtle1 of the first only
    assert second.turtles["turtle1"].theta > 0.0  # the command turned the second window's turtle


def test_each_window_answers_its_own_services_and_names_itself_in_its_log() -> None:
    world, _ = _world()
    spawned = world.call("/turtlesim2/spawn", {"name": "", "x": 1.0, "y": 1.0, "theta": 0.0})
    assert spawned.response == {"name": "turtle2"} and spawned.samples[0].name == "turtlesim2.sim"
    assert "/turtlesim2/turtle2/cmd_vel" in world.command_topics and "/turtle2/cmd_vel" not in world.command_topics
    with pytest.raises(TurtlesimError, match="serves no service '/turtlesim3/spawn'"):
        world.call("/turtlesim3/spawn", {"name": "", "x": 1.0, "y": 1.0, "theta": 0.0})


def test_two_windows_with_one_node_name_are_refused() -> None:
    twice = [TurtlesimWindow(node="/a/sim"), TurtlesimWindow(node="/a/sim")]
    scenario = Scenario(robot="turtlesim", turtlesim_windows=twice)
    with pytest.raises(TurtlesimError, match="one node name"):
        open_world(scenario)


def test_a_robot_run_has_no_turtlesim_windows() -> None:
    with pytest.raises(ValueError, match="only a turtlesim run has windows"):
        Scenario(robot="turtlebot3_burger", turtlesim_windows=[TurtlesimWindow(node="/turtlesim2/sim")])
