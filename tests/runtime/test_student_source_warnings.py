"""The grader reads a submission's Python without its compile warnings: none reach the grader's console or notes.

Python >= 3.12 warns (SyntaxWarning) for an invalid escape such as "\\d"; every Python 3 warns for ``x is 0``. With
warnings made errors, as here, a warning that escaped would be a false syntax error or an unreadable file.
"""
from __future__ import annotations

import warnings
from collections.abc import Iterator
from pathlib import Path

import pytest

from grader.runtime.client_library import client_library
from grader.runtime.int_fields import int_assignments
from grader.runtime.scripts import check_script
from grader.workspace.manifest import read_setup

NODE = '''#!/usr/bin/env python3
import re
import rospy
from geometry_msgs.msg import Twist

PATTERN = re.compile("(\\d+) m")
twist = Twist()
twist.linear.x = 1
if twist.angular.z is 0:
    print("C:\\data")
'''


@pytest.fixture(autouse=True)
def warnings_are_errors() -> Iterator[None]:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


def test_a_script_that_warns_as_it_compiles_has_no_notes(tmp_path: Path) -> None:
    script = tmp_path / "move.py"
    script.write_text(NODE)
    script.chmod(0o755)
    assert check_script(script) == []


def test_a_script_that_warns_is_still_read_for_its_imports_and_int_fields(tmp_path: Path) -> None:
    script = tmp_path / "move.py"
    script.write_text(NODE)
    assert client_library(script) == "ros1"
    assert [(a.line, a.target, a.value) for a in int_assignments(NODE)] == [(8, "twist.linear.x", 1)]


def test_a_setup_py_that_warns_is_read(tmp_path: Path) -> None:
    setup = tmp_path / "setup.py"
    setup.write_text("from setuptools import setup\npackage_name = 'my_pkg'\nNOTE = '\\d'\n"
                     "setup(name=package_name, entry_points={'console_scripts': ['move = my_pkg.move:main']})\n")
    read = read_setup(setup)
    assert (read.package_name, read.console_scripts) == ("my_pkg", ("move = my_pkg.move:main",))
