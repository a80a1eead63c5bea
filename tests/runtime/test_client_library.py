"""rospy or rclpy per script, and the console_scripts entry point `ros2 run` would start for an ament_python node."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.runtime.client_library import ROS1, ROS2, client_library, entry_point, package_findings, param_args
from grader.runtime.scripts import check_script

REFERENCE_PACKAGE = Path(__file__).resolve().parents[2] / "reference_solutions_ros2" / "part2_navigation"

SETUP = """from setuptools import find_packages, setup

package_name = '{package}'

setup(
    name=package_name,
    packages=find_packages(exclude=['test']),
    entry_points={{
        'console_scripts': [{scripts}],
    }},
)
"""


def _package(root: Path, package: str, scripts: str, module_source: str = "import rclpy\n") -> Path:
    (root / package).mkdir(parents=True)
    (root / "package.xml").write_text("<package format=\"3\"><name>x</name></package>\n")
    (root / "setup.py").write_text(SETUP.format(package=package, scripts=scripts))
    (root / package / "__init__.py").write_text("")
    script = root / package / "move_circle.py"
    script.write_text(module_source)
    return script


@pytest.mark.parametrize("source,expected", [
    ("import rospy\n", ROS1),
    ("import rclpy\nfrom rclpy.node import Node\n", ROS2),
    ("from rclpy.node import Node\n", ROS2),
    ("def main():\n    import rclpy\n", ROS2),
    ("print('no ROS at all')\n", ROS1),
    ("import rospy as rclpy_like\n", ROS1),
    ("this is not python (\n", ROS1),
])
def test_client_library_follows_imports(tmp_path: Path, source: str, expected: str) -> None:
    script = tmp_path / "node.py"
    script.write_text(source)
    assert client_library(script) == expected


def test_entry_point_of_the_reference_package() -> None:
    entry = entry_point(REFERENCE_PACKAGE / "part2_navigation" / "move_square.py")
    assert entry is not None
    assert (entry.package, entry.executable, entry.module, entry.function) == (
        "part2_navigation", "move_square", "part2_navigation.move_square", "main")
    assert entry.root == REFERENCE_PACKAGE


def test_entry_point_may_name_another_executable(tmp_path: Path) -> None:
    script = _package(tmp_path / "pkg", "my_pkg", "'circle = my_pkg.move_circle:run'")
    entry = entry_point(script)
    assert entry is not None and (entry.executable, entry.function) == ("circle", "run")


def test_no_entry_point_is_a_finding(tmp_path: Path) -> None:
    script = _package(tmp_path / "pkg", "my_pkg", "'other = my_pkg.other:main'")
    assert entry_point(script) is None
    [finding] = package_findings(script, None)
    assert "No executable found" in finding and "move_circle = my_pkg.move_circle:main" in finding


def test_a_lone_script_has_no_entry_point_and_no_package_finding(tmp_path: Path) -> None:
    script = tmp_path / "move_circle.py"
    script.write_text("import rclpy\n")
    assert entry_point(script) is None and package_findings(script, None) == []


def test_setup_py_is_read_not_run(tmp_path: Path) -> None:
    marker = tmp_path / "ran"
    script = _package(tmp_path / "pkg", "my_pkg", "'move_circle = my_pkg.move_circle:main'")
    setup = tmp_path / "pkg" / "setup.py"
    setup.write_text(f"open({str(marker)!r}, 'w').close()\n" + setup.read_text())
    assert entry_point(script) is not None and not marker.exists()


def test_rosrun_notes_only_for_ros1(tmp_path: Path) -> None:
    script = tmp_path / "move_circle.py"
    script.write_text("import rclpy\n")  # no shebang, not executable: fine for `ros2 run` and python3
    assert check_script(script, rosrun=False) == []
    assert len(check_script(script, rosrun=True)) == 2


@pytest.mark.parametrize("value", ["right", "1.0", "true", "on", "a: b", "", "~", "x y", 0.5, 3, True, False, -1e-3])
def test_param_args_give_the_value_back_as_yaml_reads_it(value) -> None:
    import yaml

    ros1 = param_args(ROS1, {"v": value})
    ros2 = param_args(ROS2, {"v": value})
    assert ros2[:2] == ("--ros-args", "-p") and ros1[0].startswith("_v:=")
    for word in (ros1[0][len("_v:="):], ros2[2][len("v:="):]):
        loaded = yaml.safe_load(word)
        assert loaded == value and type(loaded) is type(value)
