"""Which world runs a scenario: turtlesim's kinematic world, or a robot profile in MuJoCo."""
from __future__ import annotations

from sim import turtlesim, world
from sim.scenario import TURTLESIM, Pose2D, Scenario
from sim.turtlesim import TurtlesimWorld
from sim.turtlesim_windows import TurtlesimWindows
from sim.world import World

WORLD_NODE_NAMES = frozenset({world.NODE_NAME, turtlesim.NODE_NAME})  # the nodes a world stands for
AnyWorld = World | TurtlesimWorld | TurtlesimWindows  # what runs a scenario: each keeps the contract in DEVELOPERS.md


def open_world(scenario: Scenario, flavour: str = "ros1") -> AnyWorld:
    """The world that runs ``scenario`` (all keep the contract in DEVELOPERS.md, so callers need not know which), as
    the ROS version of the run's nodes has it (``flavour``: "ros1" or "ros2"; turtlesim and the TurtleBot3's LiDAR
    differ between Noetic's and Jazzy's); turtlesim with more than one window when the scenario names others."""
    if scenario.robot != TURTLESIM:
        return World(scenario, flavour=flavour)
    return TurtlesimWindows(scenario, flavour) if scenario.turtlesim_windows else TurtlesimWorld(scenario, flavour)


def command_types(scenario: Scenario, flavour: str) -> tuple[str, ...]:
    """The velocity command types the scenario's robot takes from nodes of ``flavour``: its ``command_types`` if it
    names them; turtlesim takes Twist in every ROS version; the Jazzy TurtleBot3 (and the COM2009 simulation) drive
    on TwistStamped only, the ROS 1 robots on Twist."""
    if scenario.command_types:
        return tuple(scenario.command_types)
    if scenario.robot == TURTLESIM or flavour == "ros1":
        return ("geometry_msgs/Twist",)
    return ("geometry_msgs/TwistStamped",)


def start_pose(scenario: Scenario) -> Pose2D:
    """Where the run starts: the scenario's ``initial_pose``, except that turtlesim spawns turtle1 at the centre of
    its window when the scenario names none."""
    if scenario.robot == TURTLESIM and "initial_pose" not in scenario.model_fields_set:
        return Pose2D(x=turtlesim.CENTRE, y=turtlesim.CENTRE, yaw=0.0)
    return scenario.initial_pose
