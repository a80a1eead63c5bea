"""An ament_python package installs into its share folder what setup.py's data_files lists, read as data: the forms
the ROS 2 launch tutorial and course packages write are understood, a launch file they leave out is refused with
ros2launch's own words and the line to add, and data_files that cannot be read without running setup.py keep the
usual launch/ and config/."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.launch import LaunchError
from grader.launch.ros2_index import installed
from grader.launch.ros2_specs import ros2_node_specs
from grader.workspace import read_workspace
from tests.workspace.workspace_helpers import MANIFEST, write

SETUP = """import os
from glob import glob
from setuptools import setup

package_name = 'tb_pkg'
setup(
    name=package_name,
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        {entries}
    ],
    entry_points={{'console_scripts': ['mover = tb_pkg.mover:main']}},
)
"""
FILES = ("launch/a.launch.py", "launch/b.launch.xml", "launch/c.launch.yaml", "launch/README.md", "config/p.yaml")


def _package(root: Path, entries: str) -> Path:
    folder = root / "tb_pkg"
    write(folder / "package.xml", MANIFEST.format(name="tb_pkg", buildtool="ament_python", extra="",
                                                  build_type="ament_python"))
    write(folder / "setup.py", SETUP.format(entries=entries))
    write(folder / "tb_pkg" / "__init__.py", "")
    for name in FILES:
        write(folder / name, "")
    return folder


def _installed(root: Path, entries: str) -> set[str]:
    folder = _package(root, entries)
    package = read_workspace(root).package("tb_pkg")
    assert package is not None
    return {name for name in FILES if installed(package, folder / name)}


@pytest.mark.parametrize(("entries", "expected"), [
    # the ROS 2 launch tutorial's form: every *launch.py/.xml/.yaml
    ("(os.path.join('share', package_name, 'launch'), glob(os.path.join('launch', '*launch.[pxy][yma]*'))),",
     {"launch/a.launch.py", "launch/b.launch.xml", "launch/c.launch.yaml"}),
    ("(os.path.join('share', package_name, 'launch'), glob('launch/*')),",
     {"launch/a.launch.py", "launch/b.launch.xml", "launch/c.launch.yaml", "launch/README.md"}),
    ("('share/' + package_name + '/launch', glob('launch/*.launch.py')),", {"launch/a.launch.py"}),
    ("(f'share/{package_name}/launch', ['launch/b.launch.xml']), "
     "(f'share/{package_name}/config', glob('config/*.yaml') + ['launch/c.launch.yaml']),",
     {"launch/b.launch.xml", "launch/c.launch.yaml", "config/p.yaml"}),
    ("", set()),  # nothing but package.xml: no launch file is installed
    ("('share/other_pkg/launch', glob('launch/*')),", set()),  # another package's share is not this one's
    ("('share/' + package_name, glob('../*/launch/*')),", set()),  # nothing from outside the package
])
def test_data_files_install_what_they_list(tmp_path: Path, entries: str, expected: set[str]) -> None:
    assert _installed(tmp_path, entries) == expected


@pytest.mark.parametrize("entries", [
    "('share/' + package_name + '/launch', [f for f in glob('launch/*') if f.endswith('.py')]),",
    "('share/' + package_name + '/launch', launch_files()),",
])
def test_data_files_that_cannot_be_read_as_data_keep_launch_and_config(tmp_path: Path, entries: str) -> None:
    assert _installed(tmp_path, entries) == set(FILES)


def test_a_launch_file_data_files_leaves_out_is_refused_with_ros2_launch_s_words(tmp_path: Path) -> None:
    folder = _package(tmp_path, "('share/' + package_name + '/launch', glob('launch/*.launch.xml')),")
    with pytest.raises(LaunchError) as caught:
        ros2_node_specs(folder / "launch" / "a.launch.py", read_workspace(tmp_path), {}, None)
    assert str(caught.value) == (
        "file 'a.launch.py' was not found in the share directory of package 'tb_pkg' which is at "
        "'/rosgrade/install/tb_pkg/share/tb_pkg': a.launch.py is in the package, but its build does not install it. "
        "To install it, add (os.path.join('share', package_name, 'launch'), glob('launch/*')) to data_files in "
        "setup.py (with `import os` and `from glob import glob`), then colcon build again.")
