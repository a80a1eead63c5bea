"""Builds small interface packages on disk for the interface tests (ament_cmake for ROS 2, catkin for ROS 1)."""
from __future__ import annotations

from pathlib import Path

from grader.interfaces import InterfaceSet, run_interfaces
from grader.workspace import read_workspace

AMENT_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.0</version><description>x</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend><buildtool_depend>rosidl_default_generators</buildtool_depend>
<member_of_group>rosidl_interface_packages</member_of_group>
<export><build_type>ament_cmake</build_type></export></package>
"""
CATKIN_XML = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><version>0.0.0</version><description>x</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>catkin</buildtool_depend><build_depend>message_generation</build_depend></package>
"""


def package(root: Path, name: str, files: dict[str, str], flavour: str = "ros2") -> Path:
    """A package ``name`` under ``root/src`` whose build generates ``files`` ({"msg/A.msg": text, ...})."""
    folder = root / "src" / name
    for relative, text in files.items():
        (folder / relative).parent.mkdir(parents=True, exist_ok=True)
        (folder / relative).write_text(text)
    listed = " ".join(f'"{f}"' for f in files)
    if flavour == "ros2":
        (folder / "package.xml").write_text(AMENT_XML.format(name=name))
        (folder / "CMakeLists.txt").write_text(
            f"cmake_minimum_required(VERSION 3.8)\nproject({name})\nfind_package(ament_cmake REQUIRED)\n"
            f"rosidl_generate_interfaces(${{PROJECT_NAME}} {listed})\nament_package()\n")
    else:
        (folder / "package.xml").write_text(CATKIN_XML.format(name=name))
        kinds = {"msg": "add_message_files", "srv": "add_service_files", "action": "add_action_files"}
        calls = "".join(f"{kinds[k]}(FILES {' '.join(Path(f).name for f in files if f.startswith(k + '/'))})\n"
                        for k in kinds if any(f.startswith(k + "/") for f in files))
        (folder / "CMakeLists.txt").write_text(
            f"cmake_minimum_required(VERSION 3.0.2)\nproject({name})\nfind_package(catkin REQUIRED COMPONENTS "
            f"message_generation)\n{calls}generate_messages(DEPENDENCIES std_msgs)\ncatkin_package()\n")
    return folder


def interfaces(root: Path, flavour: str = "ros2") -> InterfaceSet:
    return run_interfaces(read_workspace(root), flavour)
