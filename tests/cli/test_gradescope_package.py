"""The Gradescope package's scripts: setup.sh picks a Python rosgrade can run on, and (opt-in, root, minutes) the
whole package builds and grades in a Debian chroot laid out as Gradescope lays out /autograder."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import zipfile
from pathlib import Path

import pytest

from grader.cli import main

HERE = Path(__file__).parent
CHROOT_SCRIPT = HERE / "gradescope_chroot.sh"
EXAMPLE = HERE.parents[1] / "submissions_example" / "dana_swapped"


@pytest.fixture
def package(grading) -> dict[str, str]:
    """The text of each script in a freshly built autograder zip."""
    assert main(["gradescope-package", "--task", "move_circle", "--out", "ag.zip"]) == 0
    with zipfile.ZipFile("ag.zip") as archive:
        return {name: archive.read(name).decode() for name in ("setup.sh", "run_autograder")}


def fake_python(folder: Path, name: str, new_enough: bool) -> None:
    """An interpreter stand-in that answers setup.sh's version probe (exit 0: new enough)."""
    script = folder / name
    script.write_text(f"#!/bin/sh\n[ \"$1\" = --version ] && echo {name} && exit 0\nexit {0 if new_enough else 1}\n")
    script.chmod(0o755)


def suitable_python(setup: str, path: Path) -> subprocess.CompletedProcess[str]:
    function = setup[setup.index("suitable_python() {"):setup.index("\n}\n") + 3]
    return subprocess.run(["/bin/bash", "-c", f"{function}\nsuitable_python"], capture_output=True, text=True,
                          env={"PATH": str(path)}, check=False)


def test_setup_prefers_a_python_new_enough_over_ubuntu_2204s_310(package, tmp_path):
    fake_python(tmp_path, "python3", new_enough=False)
    fake_python(tmp_path, "python3.11", new_enough=True)
    found = suitable_python(package["setup.sh"], tmp_path)
    assert found.returncode == 0 and found.stdout.strip() == str(tmp_path / "python3.11")


def test_setup_reports_no_python_when_only_310_exists(package, tmp_path):
    fake_python(tmp_path, "python3", new_enough=False)
    assert suitable_python(package["setup.sh"], tmp_path).returncode == 1


def test_setup_installs_bubblewrap_and_python311_as_the_fallback(package):
    setup = package["setup.sh"]
    assert "bubblewrap" in setup and "python3.11 python3.11-venv" in setup and "chmod -R a+rX /opt/rosgrade" in setup


def test_run_autograder_hides_the_autograder_from_student_uids(package):
    run = package["run_autograder"]
    assert "chmod o= /autograder/source /autograder/results" in run and "runuser" not in run


@pytest.mark.skipif(os.environ.get("ROSGRADE_CHROOT_TEST") != "1",
                    reason="set ROSGRADE_CHROOT_TEST=1 (root, mmdebstrap, network to Debian and PyPI; ~5 min)")
def test_package_builds_and_grades_in_a_debian_chroot(tmp_path):
    if os.geteuid() != 0 or shutil.which("mmdebstrap") is None:
        pytest.skip("needs root and mmdebstrap (apt-get install mmdebstrap)")
    zip_path = tmp_path / "autograder.zip"
    assert main(["gradescope-package", "--task", "move_circle", "--out", str(zip_path)]) == 0
    tarball = os.environ.get("ROSGRADE_CHROOT_TAR", "")
    done = subprocess.run([str(CHROOT_SCRIPT), str(zip_path), str(EXAMPLE), str(tmp_path / "chroot"), tarball],
                          capture_output=True, text=True, timeout=3600, check=False)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    results = json.loads(done.stdout[done.stdout.index("{"):])
    assert results["score"] == 6.0 and len(results["tests"]) == 3  # dana swapped v and ω: radius criterion lost
    assert "published 201 messages on /cmd_vel" in results["output"]  # the notes reach Gradescope's summary
