"""turtlesim's ROS 2 interfaces (Pose, Color, five services, RotateAbsolute) hash as real rosidl hashes them.

The interface files in turtlesim_ros2_interfaces/ hold the fields ros/ros_tutorials (rolling at 1.8.2, where Jazzy's
turtlesim branched) declares in turtlesim/msg/*.msg, srv/*.srv and action/RotateAbsolute.action: names and types
only. turtlesim_rosidl_record.json is what the real generators (rosidl_adapter, rosidl_generator_type_description
from the ROS 2 venv's wheels) gave for them: ``real_rosidl.py <that folder> <venv> <work> --hashes-only``.
"""
from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest

from grader.nodelib.ros2.rosgrade_rosidl import _defs as node_defs
from grader.recording.ros2_messages import ros2_catalog

HERE = Path(__file__).resolve().parent
PACKAGE = HERE / "turtlesim_ros2_interfaces" / "turtlesim"
RECORD = HERE / "turtlesim_rosidl_record.json"
REAL_ROSIDL = HERE.parent / "interfaces" / "real_rosidl.py"
VENV = Path(os.environ.get("ROSGRADE_ROS2_VENV", "/opt/rosgrade-ros2-jazzy-venv"))


def _real() -> dict[str, str]:
    return json.loads(RECORD.read_text())["hashes"]


def test_the_node_side_classes_carry_rosidls_hashes() -> None:
    """What ``from turtlesim.msg import Pose`` in a student's rclpy node says its type hash is, for every type."""
    ours = {name: json.loads(entry)[2] for name, entry in node_defs.MESSAGES.items()} | node_defs.SERVICES \
        | node_defs.ACTIONS
    real = _real()
    # 2 messages, 5 services of 4 types, an action of 13
    assert len([name for name in real if name.startswith("turtlesim/")]) == 35
    assert {name: ours.get(name) for name in real} == real


def test_the_grader_catalog_records_rosidls_hashes() -> None:
    """The hashes a recording's schemas and the grader's side of the channel carry (it has no service events)."""
    catalog = ros2_catalog()
    real = _real()
    services = {n for n in real if n.startswith("turtlesim/srv/") and n.count("_") == 0} | {
        n for n in real if n.endswith(("_SendGoal", "_GetResult"))}
    ours = {name: catalog.service_md5sum(name) if name in services else catalog.md5sum(name)
            for name in real if name != "turtlesim/action/RotateAbsolute" and not name.endswith("_Event")}
    assert len(ours) == 30  # all 38 but the action itself and the 7 service events
    assert ours == {name: value for name, value in real.items() if name in ours}


def _venv_reason() -> str | None:
    if not (VENV / "bin" / "python").exists():
        return f"no ROS 2 venv at {VENV} (.ci/ros2-venv makes it)"
    return None


@pytest.mark.skipif(_venv_reason() is not None, reason=str(_venv_reason()))
def test_record_is_what_the_real_generators_give_now(tmp_path: Path) -> None:
    env = {**os.environ, "AMENT_PREFIX_PATH": str(VENV), "PYTHONPATH": str(REAL_ROSIDL.parent)}
    out = subprocess.run([str(VENV / "bin" / "python"), str(REAL_ROSIDL), str(PACKAGE), str(VENV), str(tmp_path),
                          "--hashes-only"], capture_output=True, text=True, env=env, timeout=300, check=True,
                         cwd=REAL_ROSIDL.parent)
    assert json.loads(out.stdout) == json.loads(RECORD.read_text())
