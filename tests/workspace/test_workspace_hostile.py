"""Hostile package files give findings in bounded time: FIFOs and devices are never read, nesting never recurses."""
from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from grader.runtime.client_library import client_library, import_roots, package_findings
from grader.workspace import cmake, read_package, read_workspace
from grader.workspace.manifest import ManifestError, read_manifest, read_setup

from workspace_helpers import cmake_package


def test_a_fifo_in_place_of_cmakelists_is_never_read(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    (folder / "CMakeLists.txt").unlink()
    os.mkfifo(folder / "CMakeLists.txt")
    started = time.monotonic()
    package = read_package(folder)
    assert time.monotonic() - started < 2.0
    assert any("no CMakeLists.txt" in f for f in package.findings)


@pytest.mark.parametrize("read", [cmake.read, read_setup, read_manifest])
def test_build_files_are_read_only_when_regular(tmp_path: Path, read) -> None:
    fifo = tmp_path / "file"
    os.mkfifo(fifo)
    with pytest.raises((cmake.CMakeError, ManifestError), match="not a regular file"):
        read(fifo)


def test_a_fifo_package_xml_is_no_package(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    (folder / "package.xml").unlink()
    os.mkfifo(folder / "package.xml")
    assert read_workspace(tmp_path).folders == {}


def test_parentheses_nested_deeper_than_python_recurses(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p", "project(p)\nif(" + "(" * 100_000 + ")" * 100_000 + ")\nendif()\n")
    package = read_package(folder)
    assert any("ament_package()" in f for f in package.findings)


def test_a_script_whose_package_is_broken_still_gets_a_client_library(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p", "project(p\n")
    script = folder / "scripts" / "move_circle.py"
    assert client_library(script) == "ros2"
    assert any('missing ending ")"' in f for f in package_findings(script, None))


def test_python_packages_outside_the_package_are_not_imported(tmp_path: Path) -> None:
    outside = tmp_path / "grader_secrets"
    (outside / "secrets").mkdir(parents=True)
    (outside / "secrets" / "__init__.py").write_text("")
    text = (f"project(p)\nfind_package(ament_cmake_python REQUIRED)\n"
            f"ament_python_install_package(secrets PACKAGE_DIR {outside / 'secrets'})\nament_package()\n")
    folder = cmake_package(tmp_path / "p", "p", text)
    (folder / "p_modules").rename(folder / "real_tools")
    (folder / "p_modules").symlink_to(outside / "secrets")
    package = read_package(folder)
    assert package.python_packages == ()
    assert len([f for f in package.findings if "from outside the package p" in f]) == 1
    assert import_roots(folder / "scripts" / "move_circle.py") == ()
