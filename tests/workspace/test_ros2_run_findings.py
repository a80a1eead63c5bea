"""What `ros2 run` and colcon would say about a script in its package, its client library when it does not parse,
and the folders its imports come from."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.runtime.client_library import ROS1, ROS2, client_library, entry_point, import_roots, package_findings
from grader.workspace import read_workspace

from workspace_helpers import MANIFEST, TEMPLATE, cmake_package

UNPARSEABLE = "#!/usr/bin/env python3\n{imports}\ndef main():\nprint('not indented')\n"


def _script(folder: Path, text: str, name: str = "move_circle.py") -> Path:
    script = folder / "scripts" / name
    script.write_text(text)
    script.chmod(0o755)
    return script


@pytest.mark.parametrize("imports,expected", [
    ("import rclpy\nfrom rclpy.node import Node", ROS2),
    ("from rclpy.node import Node", ROS2),
    ("import os, rclpy", ROS2),
    ("import rospy", ROS1),
])
def test_a_lone_script_that_does_not_parse_goes_by_its_import_lines(tmp_path: Path, imports: str,
                                                                     expected: str) -> None:
    script = tmp_path / "node.py"
    script.write_text(UNPARSEABLE.format(imports=imports))
    assert client_library(script) == expected


def test_an_rclpy_script_with_an_indentation_error_in_an_ament_package_is_ros2(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    script = _script(folder, UNPARSEABLE.format(imports="# imports come later"))
    assert client_library(script) == ROS2


def test_an_unparseable_script_in_a_rospy_catkin_package_is_ros1(tmp_path: Path) -> None:
    folder = tmp_path / "beginner"
    folder.mkdir()
    (folder / "package.xml").write_text(MANIFEST.format(name="beginner", buildtool="catkin", build_type="catkin",
                                                        extra="").replace("rclpy", "rospy"))
    (folder / "CMakeLists.txt").write_text("project(beginner)\n")
    script = folder / "mover.py"
    script.write_text(UNPARSEABLE.format(imports=""))
    assert client_library(script) == ROS1


def test_a_script_importing_only_its_package_s_modules_takes_the_package_s_library(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    script = _script(folder, "#!/usr/bin/env python3\nfrom p_modules.tb3_tools import quaternion_to_euler\n")
    assert client_library(script) == ROS2


def test_the_template_package_has_no_findings_and_imports_from_its_folder(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    script = _script(folder, "#!/usr/bin/env python3\nimport rclpy\nfrom p_modules.tb3_tools import x\n")
    assert entry_point(script) is None
    assert package_findings(script, None) == []
    assert import_roots(script) == (folder.resolve(),)


def test_a_script_missing_from_install_programs(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    script = _script(folder, "#!/usr/bin/env python3\nimport rclpy\n", "move_square.py")
    [finding] = package_findings(script, None)
    assert "`ros2 run p move_square.py` would say 'No executable found'" in finding
    assert "Add scripts/move_square.py to install(PROGRAMS" in finding


def test_a_script_without_the_execute_bit(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    script = folder / "scripts" / "move_circle.py"
    script.chmod(0o644)
    [finding] = package_findings(script, None)
    assert "--symlink-install" in finding and "chmod +x scripts/move_circle.py" in finding


@pytest.mark.parametrize("first_line,words", [
    ("import rclpy", "Exec format error"),
    ("#!/usr/bin/env python3\r", "python3\\r"),
])
def test_what_ros2_run_needs_on_the_first_line(tmp_path: Path, first_line: str, words: str) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    script = _script(folder, f"{first_line}\nimport rclpy\n")
    [finding] = package_findings(script, None)
    assert words in finding


def test_a_script_installed_as_a_plain_file(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p", TEMPLATE.format(name="p").replace("install(PROGRAMS",
                                                                                   "install(FILES"))
    [finding] = package_findings(folder / "scripts" / "move_circle.py", None)
    assert "as a plain file" in finding and "install(PROGRAMS" in finding


def test_modules_the_build_does_not_install(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("ament_python_install_package(${PROJECT_NAME}_modules)\n", "")
    folder = cmake_package(tmp_path / "p", "p", text)
    script = _script(folder, "#!/usr/bin/env python3\nimport rclpy\nfrom p_modules.tb3_tools import x\n")
    [finding] = package_findings(script, None)
    assert "ModuleNotFoundError: No module named 'p_modules'" in finding
    assert "p/CMakeLists.txt" in finding and "ament_python_install_package(${PROJECT_NAME}_modules)" in finding
    assert import_roots(script) == (folder.resolve(),)  # graded as if it were installed


def test_a_wrong_package_name_in_an_import(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "part2_navigation")
    script = _script(folder, "#!/usr/bin/env python3\nimport rclpy\n"
                             "from part1_pubsub_modules.tb3_tools import quaternion_to_euler\n")
    [finding] = package_findings(script, None)
    assert "No module named 'part1_pubsub_modules'" in finding
    assert "import from part2_navigation_modules.tb3_tools instead" in finding


def test_an_import_of_something_that_exists_is_no_finding(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    (folder / "scripts" / "helpers.py").write_text("")
    script = _script(folder, "#!/usr/bin/env python3\nimport math, numpy, rclpy, helpers\n"
                             "from geometry_msgs.msg import TwistStamped\n")
    assert package_findings(script, None) == []


def test_package_findings_come_with_the_script_s(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("ament_package()\n", "")
    folder = cmake_package(tmp_path / "p", "p", text)
    [finding] = package_findings(folder / "scripts" / "move_circle.py", None)
    assert "ament_package()" in finding


def test_a_workspace_resolves_imports_across_packages(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    nav = cmake_package(src / "part2_navigation")
    tools = cmake_package(src / "team_tools", "team_tools")
    script = _script(nav, "#!/usr/bin/env python3\nimport rclpy\nfrom team_tools_modules.tb3_tools import x\n")
    workspace = read_workspace(tmp_path)
    assert import_roots(script, workspace) == (nav.resolve(), tools.resolve())
    assert package_findings(script, None, workspace) == []


def test_a_lone_script_imports_nothing_from_a_workspace(tmp_path: Path) -> None:
    script = tmp_path / "move_circle.py"
    script.write_text("import rclpy\n")
    assert import_roots(script) == ()


def test_roots_come_from_packages_of_the_script_s_ros_version(tmp_path: Path) -> None:
    nav = cmake_package(tmp_path / "src" / "part2_navigation")
    beginner = tmp_path / "src" / "beginner"
    beginner.mkdir()
    (beginner / "package.xml").write_text(MANIFEST.format(name="beginner", buildtool="catkin", build_type="catkin",
                                                          extra=""))
    (beginner / "CMakeLists.txt").write_text("project(beginner)\ncatkin_python_setup()\n")
    (beginner / "setup.py").write_text("from setuptools import setup\nsetup(packages=['beginner_tools'], "
                                       "package_dir={'': 'src'})\n")
    (beginner / "src" / "beginner_tools").mkdir(parents=True)
    (beginner / "src" / "beginner_tools" / "__init__.py").write_text("")
    mover = beginner / "mover.py"
    mover.write_text("import rospy\n")
    workspace = read_workspace(tmp_path)
    assert import_roots(mover, workspace, ROS1) == ((beginner / "src").resolve(),)
    assert import_roots(nav / "scripts" / "move_circle.py", workspace, ROS2) == (nav.resolve(),)
