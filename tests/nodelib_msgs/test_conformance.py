"""Runs every probe in probes.py under Debian's real ROS 1 stack and under rosgrade's nodelib; outputs must match."""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from grader.nodelib import pythonpath

from .probes import PROBES

HERE = Path(__file__).parent
NODELIB_PATH = pythonpath("ros1")
REAL_PYTHON = "/usr/bin/python3"
# numpy 2's vectorised sin/cos and LAPACK differ from the real stack's numpy 1.x in the last bit here;
# these probes are compared to 1e-12 instead of exactly.
LAST_BIT_PROBES = {"tft.random_quaternion([0.1, 0.5, 0.9])", "tft.inverse_matrix(tft.euler_matrix(0.1, 0.2, 0.3))",
                   "tft.random_rotation_matrix([0.2, 0.4, 0.6])"}


def _real_ros_available() -> bool:
    if not os.path.exists(REAL_PYTHON):
        return False
    probe = subprocess.run([REAL_PYTHON, "-c", "import genpy, tf, geometry_msgs.msg, nav_msgs.msg"],
                           capture_output=True, env={"PATH": "/usr/bin:/bin"})
    return probe.returncode == 0


pytestmark = [pytest.mark.realros,
              pytest.mark.skipif(not _real_ros_available(),
                                 reason="real ROS 1 (python3-genpy, python3-tf, msgs) is not installed at /usr/bin/python3")]


def _run(python: str, pythonpath: str | None) -> list:
    env = {"PATH": "/usr/bin:/bin", "HOME": os.environ.get("HOME", "/tmp")}
    if pythonpath:
        env["PYTHONPATH"] = pythonpath
    done = subprocess.run([python, str(HERE / "probes.py")], capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    return [json.loads(line) for line in done.stdout.splitlines()]


@pytest.fixture(scope="module")
def outputs() -> tuple[list, list]:
    return _run(REAL_PYTHON, None), _run(sys.executable, NODELIB_PATH)


def _floats(rendered) -> list[float]:
    if isinstance(rendered, list) and len(rendered) == 2 and rendered[0] == "float":
        return [float(rendered[1])]
    if isinstance(rendered, list):
        return [f for item in rendered for f in _floats(item)]
    return []


def test_every_probe_matches_real_ros(outputs):
    real, ours = outputs
    assert len(real) == len(ours) == len(PROBES)
    mismatches = []
    for probe, expected, got in zip(PROBES, real, ours):
        if probe in LAST_BIT_PROBES:
            a, b = _floats(expected), _floats(got)
            if len(a) != len(b) or any(not math.isclose(x, y, rel_tol=0, abs_tol=1e-12) for x, y in zip(a, b)):
                mismatches.append((probe, expected, got))
        elif expected != got:
            mismatches.append((probe, expected, got))
    report = "\n".join("%s\n  real: %s\n  ours: %s" % m for m in mismatches)
    assert not mismatches, "%d of %d probes differ from real ROS:\n%s" % (len(mismatches), len(PROBES), report)
