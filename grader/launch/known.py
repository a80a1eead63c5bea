"""Packages a student's launch file may name that are not theirs: simulator launch files mapped onto rosgrade robots,
and packages whose nodes the grader provides.

``$(find turtlebot3_gazebo)`` resolves to where Noetic installs it, and including one of its world launch files
asks for a rosgrade world instead of Gazebo. turtlesim's nodes are started with ``<node pkg="turtlesim">``
(``grader.launch.turtlesim``). Every other package is "not available in the grader".
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import PurePosixPath

from grader.provided_nodes import TURTLESIM_EXECUTABLES

SHARE = PurePosixPath("/opt/ros/noetic/share")


class UnknownPackage(Exception):
    """A package that is neither the student's nor one the grader simulates."""


@dataclass(frozen=True)
class WorldFile:
    """A simulator launch file: its args with their defaults, and how they pick the robot and its spawn pose."""

    args: dict[str, str]
    x_arg: str
    y_arg: str
    yaw_arg: str | None
    robot: str | None  # None: chosen by the `model` arg


_TURTLEBOT3_MODELS = {"burger": "turtlebot3_burger", "waffle": "turtlebot3_waffle", "waffle_pi": "turtlebot3_waffle"}
# The course sets TURTLEBOT3_MODEL=waffle in ~/.bashrc; the grader has no student shell to read it from.
DEFAULT_ENV = {"TURTLEBOT3_MODEL": "waffle", "ROS_DISTRO": "noetic", "ROS_VERSION": "1", "ROS_PYTHON_VERSION": "3"}


def _turtlebot3(x: str, y: str) -> WorldFile:
    return WorldFile(args={"model": "$(env TURTLEBOT3_MODEL)", "x_pos": x, "y_pos": y, "z_pos": "0.0"},
                     x_arg="x_pos", y_arg="y_pos", yaw_arg=None, robot=None)


def _husky() -> WorldFile:
    return WorldFile(args={"x": "0.0", "y": "0.0", "z": "0.0", "yaw": "0.0", "world_name": "", "laser_enabled": "true",
                           "realsense_enabled": "false"},
                     x_arg="x", y_arg="y", yaw_arg="yaw", robot="husky_a200")


WORLD_FILES: dict[tuple[str, str], WorldFile] = {
    ("turtlebot3_gazebo", "launch/turtlebot3_empty_world.launch"): _turtlebot3("0.0", "0.0"),
    ("turtlebot3_gazebo", "launch/turtlebot3_world.launch"): _turtlebot3("-2.0", "-0.5"),
    ("husky_gazebo", "launch/husky_empty_world.launch"): _husky(),
    ("husky_gazebo", "launch/empty_world.launch"): _husky(),
    ("husky_gazebo", "launch/husky_playpen.launch"): _husky(),
}
SIMULATED_PACKAGES = {package for package, _ in WORLD_FILES}
# Packages with nodes the grader provides but no files: <node pkg=...> works, $(find ...) does not.
NODE_PACKAGES = {"turtlesim": ("turtlesim_node", *TURTLESIM_EXECUTABLES)}


def package_path(name: str) -> str:
    """Where Noetic installs a package the grader simulates; UnknownPackage for any other."""
    if name in SIMULATED_PACKAGES:
        return str(SHARE / name)
    raise UnknownPackage(not_available(name))


def not_available(name: str) -> str:
    """Why a package cannot be used in the grader, in one sentence."""
    if name in NODE_PACKAGES:
        return (f"package {name} has no files in the grader; start its nodes with <node pkg=\"{name}\" "
                f"type=...> ({', '.join(NODE_PACKAGES[name])})")
    simulated = ", ".join(sorted(SIMULATED_PACKAGES))
    return (f"package {name} is not available in the grader: a launch file may use your own packages and the "
            f"world launch files of {simulated}")


def world_file(path: str) -> tuple[str, str, WorldFile] | None:
    """(package, file inside it, description) when ``path`` is a simulated launch file; None when outside them."""
    pure = PurePosixPath(path)
    try:
        relative = pure.relative_to(SHARE)
    except ValueError:
        return None
    package, inside = relative.parts[0], PurePosixPath(*relative.parts[1:]).as_posix()
    if (package, inside) in WORLD_FILES:
        return package, inside, WORLD_FILES[(package, inside)]
    known = ", ".join(f for p, f in WORLD_FILES if p == package)
    raise UnknownPackage(f"{package}/{inside} is not simulated by the grader; the launch files it knows in "
                         f"{package} are: {known}")


def robot_for(world: WorldFile, args: dict[str, str]) -> str:
    """The rosgrade robot profile a world file's args ask for."""
    if world.robot is not None:
        return world.robot
    model = args["model"]
    if model not in _TURTLEBOT3_MODELS:
        raise UnknownPackage(f"model:={model} is not a TurtleBot3 model; expected one of "
                             f"{', '.join(_TURTLEBOT3_MODELS)}")
    return _TURTLEBOT3_MODELS[model]
