"""The packages a ROS 2 launch file sees, as colcon would install the submission: share folders, executables, and
the packages that are not the student's (turtlesim: the world's; rviz2, gazebo, nav2...: external, never run)."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from grader.workspace import read_workspace
from grader.workspace.model import Package, Workspace

INSTALL = "/rosgrade/install"  # the install prefix the launch file is shown (nothing is installed there)
WORLD_PACKAGES = {"turtlesim": ("turtlesim_node", "turtle_teleop_key", "mimic", "draw_square")}
EXTERNAL_PACKAGES = ("rviz2", "gazebo_ros", "ros_gz_sim", "ros_gz_bridge", "nav2_bringup", "nav2_map_server",
                     "slam_toolbox", "robot_state_publisher", "joint_state_publisher", "joint_state_publisher_gui",
                     "turtlebot3_gazebo", "turtlebot3_bringup", "turtlebot3_navigation2", "turtlebot3_cartographer",
                     "cartographer_ros", "teleop_twist_keyboard", "tf2_ros", "rqt_graph", "rosbridge_server")


def installed(package: Package, path: Path) -> bool:
    """Whether the build installs `path` into the package's share folder (install(DIRECTORY), data_files)."""
    resolved = path.resolve()
    return any(resolved == folder.resolve() or folder.resolve() in resolved.parents for folder in package.share)


def not_installed(package: Package, path: Path) -> str:
    """What `ros2 launch PACKAGE FILE` prints for a file its package's build does not install, and the line to add."""
    folder = path.parent.relative_to(package.folder).as_posix() if package.folder in path.parents else "launch"
    if package.build_type == "ament_python":
        line = (f"add (os.path.join('share', package_name, '{folder}'), glob('{folder}/*')) to data_files in "
                "setup.py (with `import os` and `from glob import glob`)")
    else:
        line = f"add install(DIRECTORY {folder} DESTINATION share/${{PROJECT_NAME}}) to CMakeLists.txt"
    return (f"file '{path.name}' was not found in the share directory of package '{package.name}' which is at "
            f"'{INSTALL}/{package.name}/share/{package.name}': {path.name} is in the package, but its build does "
            f"not install it. To install it, {line}, then colcon build again.")


def launch_index(workspace: Workspace) -> dict[str, dict[str, Any]]:
    """name -> share folder, install prefix and executables, for ament_index_python inside the sandbox."""
    found: dict[str, dict[str, Any]] = {}
    for name, executables in WORLD_PACKAGES.items():
        found[name] = {"share": f"/opt/ros/jazzy/share/{name}", "prefix": "/opt/ros/jazzy",
                       "executables": list(executables), "world": True}
    for name in EXTERNAL_PACKAGES:
        found[name] = {"share": f"/opt/ros/jazzy/share/{name}", "prefix": "/opt/ros/jazzy", "executables": [],
                       "external": True}
    for package in workspace.packages():
        found[package.name] = {"share": str(package.folder), "prefix": f"{INSTALL}/{package.name}",
                               "executables": sorted(e.name for e in package.executables)}
    return found


def workspace_for(path: Path, given: Path | None) -> Workspace:
    """The workspace a launch file is read in: `given`, else the folder above the file's package."""
    if given is not None:
        return read_workspace(given)
    start = path.resolve().parent
    for folder in (start, *start.parents):
        if (folder / "package.xml").is_file():
            return read_workspace(folder.parent)
    return read_workspace(start)
