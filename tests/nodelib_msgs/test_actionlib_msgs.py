"""actionlib_msgs and actionlib's own test actions in rosgrade's genpy: md5sums, slots and text as Debian's
python3-actionlib-msgs and python3-actionlib 1.14 generate them (recorded below; compared live where installed)."""
from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from grader.nodelib import pythonpath

REAL_PYTHON = "/usr/bin/python3"
# Recorded from Debian's generated classes (python3-actionlib 1.14.0, python3-actionlib-msgs).
RECORDED_MD5 = {
    "actionlib_msgs/GoalID": "302881f31927c1df708a2dbab0e80ee8",
    "actionlib_msgs/GoalStatus": "d388f9b87b3c471f784434d671988d4a",
    "actionlib_msgs/GoalStatusArray": "8b2b82f13216d0a8ea88bd3af735e619",
    "actionlib/TestAction": "991e87a72802262dfbe5d1b3cf6efc9a",
    "actionlib/TestActionGoal": "348369c5b403676156094e8c159720bf",
    "actionlib/TestActionResult": "3d669e3a63aa986c667ea7b0f46ce85e",
    "actionlib/TestActionFeedback": "6d3d0bf7fb3dda24779c010a9f3eb7cb",
    "actionlib/TestGoal": "18df0149936b7aa95588e3862476ebde",
    "actionlib/TwoIntsAction": "6d1aa538c4bd6183a2dfb7fcac41ee50",
    "actionlib/TwoIntsActionGoal": "684a2db55d6ffb8046fb9d6764ce0860",
    "actionlib/TwoIntsGoal": "36d09b846be0b371c5f190354dd3153e",
    "actionlib/TwoIntsActionFeedback": "aae20e09065c3809e8a8e87c4c8953fd",
    "actionlib/TestRequestGoal": "db5d00ba98302d6c6dd3737e9a03ceea",
}
_PROBE = """
import importlib, json, sys
out = {}
for name in sys.argv[1:]:
    package, cls = name.split("/")
    c = getattr(importlib.import_module(package + ".msg"), cls)
    out[name] = [c._md5sum, list(c.__slots__), list(c._slot_types)]
from actionlib.msg import TestActionFeedback
from actionlib_msgs.msg import GoalStatus
out["str"] = str(TestActionFeedback())
out["constants"] = [GoalStatus.PENDING, GoalStatus.PREEMPTING, GoalStatus.RECALLED, GoalStatus.LOST]
print(json.dumps(out, sort_keys=True))
"""


def _describe(python: str, path: str | None) -> dict:
    env = {"PATH": "/usr/bin:/bin", "HOME": os.environ.get("HOME", "/tmp")}
    if path:
        env["PYTHONPATH"] = path
    done = subprocess.run([python, "-c", _PROBE, *RECORDED_MD5], capture_output=True, text=True, env=env, timeout=60)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _real_available() -> bool:
    return os.path.exists(REAL_PYTHON) and subprocess.run(
        [REAL_PYTHON, "-c", "import actionlib.msg, actionlib_msgs.msg"], capture_output=True,
        env={"PATH": "/usr/bin:/bin"}).returncode == 0


@pytest.fixture(scope="module")
def ours() -> dict:
    return _describe(sys.executable, pythonpath("ros1"))


def test_md5sums_as_recorded(ours: dict) -> None:
    assert {name: ours[name][0] for name in RECORDED_MD5} == RECORDED_MD5
    assert ours["constants"] == [0, 6, 8, 9]
    assert ours["actionlib/TestAction"][1] == ["action_goal", "action_result", "action_feedback"]


@pytest.mark.realros
@pytest.mark.skipif(not _real_available(), reason="Debian's python3-actionlib is not installed at /usr/bin/python3")
def test_same_as_debian(ours: dict) -> None:
    assert _describe(REAL_PYTHON, None) == ours
