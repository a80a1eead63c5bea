"""Packages written the way courses lay them out, for the workspace model's tests."""
from __future__ import annotations

from pathlib import Path

MANIFEST = """<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <buildtool_depend>{buildtool}</buildtool_depend>
  <exec_depend>rclpy</exec_depend>
  {extra}
  <export><build_type>{build_type}</build_type></export>
</package>
"""

TEMPLATE = """cmake_minimum_required(VERSION 3.8)
project({name})
find_package(ament_cmake REQUIRED)
find_package(ament_cmake_python REQUIRED)
find_package(rclpy REQUIRED)

# Install Python modules
ament_python_install_package(${{PROJECT_NAME}}_modules)

# Install Python executables
install(PROGRAMS
  scripts/move_circle.py
  DESTINATION lib/${{PROJECT_NAME}}
)

ament_package()
"""


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def cmake_package(folder: Path, name: str = "part2_navigation", cmakelists: str | None = None,
                  extra: str = "") -> Path:
    """A package from COM2009's ament_cmake template: scripts/, <name>_modules/, CMakeLists.txt, package.xml."""
    write(folder / "package.xml", MANIFEST.format(name=name, buildtool="ament_cmake", build_type="ament_cmake",
                                                   extra=extra))
    write(folder / "CMakeLists.txt", cmakelists if cmakelists is not None else TEMPLATE.format(name=name))
    write(folder / f"{name}_modules" / "__init__.py", "")
    write(folder / f"{name}_modules" / "tb3_tools.py", "def quaternion_to_euler(q):\n    return q\n")
    script = write(folder / "scripts" / "move_circle.py", "#!/usr/bin/env python3\nimport rclpy\n")
    script.chmod(0o755)
    return folder
