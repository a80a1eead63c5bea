"""An int written into a Twist's float64 field (`cmd.linear.x = 2`) in an rclpy node: what real rclpy sends, and how
rosgrade names it (the line and the fix, in the findings; the denormal values, in the criterion's hint).

Measured with ros-jazzy-rclpy 7.1.6 (the Jazzy venv, CPython 3.11): serialize_message of a Twist whose linear.x
holds the int sends the int's size word as the double's bits: RECORDED below. rosgrade's rclpy sends the same
(`as_double`); the live comparison runs where the venv is, else it is skipped saying why.
"""
from __future__ import annotations

import json
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from grader.metrics.facts import int_fields
from grader.metrics.run import Commands, RunData, Trajectory
from grader.nodelib.ros2.rosgrade_rosidl._convert import as_double
from grader.runtime.int_fields import int_assignments, int_field_findings

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "conformance_ros2"))
from real_ros2 import ros2_env, unavailable_reason, venv_python  # noqa: E402

# int written into Twist.linear.x -> the 8 bytes real rclpy put on the wire for it (little-endian, as hex)
RECORDED = {"1": "0100000000000000", "2": "0100000000000000", "100": "0100000000000000",
            "1073741824": "0200000000000000", "1099511627776": "0200000000000000",
            "4611686018427387904": "0300000000000000", "-1": "ffffffffffffffff", "-3": "ffffffffffffffff"}
PROBE = """
import json, sys
from geometry_msgs.msg import Twist
from rclpy.serialization import serialize_message
out = {}
for text in sys.argv[1:]:
    msg = Twist()
    msg.linear.x = int(text)
    out[text] = serialize_message(msg)[4:12].hex()
print(json.dumps(out))
"""


@pytest.mark.parametrize("value", sorted(RECORDED, key=int))
def test_rosgrade_sends_what_real_rclpy_sent(value: str) -> None:
    assert struct.pack("<d", as_double(int(value))).hex() == RECORDED[value]


def test_the_record_is_what_real_rclpy_sends_now(tmp_path) -> None:
    reason = unavailable_reason()
    if reason:
        pytest.skip(reason)
    done = subprocess.run([str(venv_python()), "-c", PROBE, *RECORDED], env=ros2_env(0, tmp_path),
                          capture_output=True, text=True, timeout=120, check=True)
    assert json.loads(done.stdout) == RECORDED


def test_int_assignments_are_found_with_their_lines() -> None:
    source = ("SPEED = 2\nclass N:\n    def __init__(self):\n        self.turn = -1\n    def cb(self, msg, t):\n"
              "        msg.linear.x = SPEED\n        msg.angular.z = self.turn\n        msg.linear.y = 0\n"
              "        msg.linear.x = 2.0\n        t.twist.angular.z = 3\n        msg.x = 4\n")
    assert [(a.line, a.target, a.value) for a in int_assignments(source)] == [
        (6, "msg.linear.x", 2), (7, "msg.angular.z", -1), (10, "t.twist.angular.z", 3)]
    assert int_assignments("msg.linear.x = (") == []  # Python's own error is reported elsewhere


def test_the_finding_names_the_line_what_is_sent_and_the_fix(tmp_path) -> None:
    script = tmp_path / "move.py"
    script.write_text("import rclpy\ncmd.linear.x = 2\n")
    assert int_field_findings(script) == [
        "move.py line 2: cmd.linear.x = 2 puts a Python int in a float64 field, which rclpy sends as the int's "
        "internal size word read as a double: 5e-324, not 2.0, so the command does not do what it says. Write 2.0 "
        "(or float(...))."]


def test_the_fact_names_the_components_that_carried_denormals() -> None:
    commands = Commands(np.array([0.0, 0.1]), np.array([[5e-324, 0.0, 0.0], [1.0, 0.0, 0.0]]),
                        np.array([[0.0, 0.0, 1e-323], [0.0, 0.0, 0.0]]), ("/turtle1/cmd_vel",) * 2)
    still = Trajectory.of([], [], [], [])
    assert int_fields(RunData(odometry=still, commands=commands)) == "linear.x, angular.z"
    assert int_fields(RunData(odometry=still)) == ""
