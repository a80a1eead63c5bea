"""Runs ROS 2 node-side code in subprocesses with the ros2 import roots (grader.nodelib.pythonpath) first.

The ROS 1 tests put ros1 roots (their own geometry_msgs, ...) on this process's sys.path, so nothing here imports
the ROS 2 message packages in the pytest process itself.
"""
from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
from pathlib import Path

from grader.nodelib import import_roots, pythonpath

HERE = Path(__file__).resolve().parent
REAL_VENV = Path(os.environ.get("ROSGRADE_ROS2_VENV", "/opt/rosgrade-ros2-jazzy-venv"))
REAL_PYTHON = REAL_VENV / "bin" / "python"


def run(args: list[str], python: str = sys.executable, ours: bool = True, env: dict | None = None) -> str:
    """stdout of ``python args`` (cwd: this folder); ``ours`` puts rosgrade's ros2 node path first."""
    full_env = {"PATH": "/usr/bin:/bin", "HOME": os.environ.get("HOME", "/tmp"), "PYTHONDONTWRITEBYTECODE": "1",
                "PYTHONPATH": os.pathsep.join(([pythonpath("ros2")] if ours else []) + [str(HERE)])}
    full_env.update(env or {})
    done = subprocess.run([str(python), *args], capture_output=True, text=True, env=full_env, cwd=HERE, timeout=600)
    assert done.returncode == 0, done.stderr[-4000:]
    return done.stdout


def run_json(args: list[str], **kwargs) -> object:
    return json.loads(run(args, **kwargs))


def real_venv_reason() -> str | None:
    """Why the real ROS 2 venv cannot be used, or None."""
    if not REAL_PYTHON.exists():
        return (f"no real ROS 2 venv at {REAL_VENV} (set ROSGRADE_ROS2_VENV; .ci/ros2-venv installs ros-jazzy-rclpy "
                "and the msgs)")
    probe = subprocess.run([str(REAL_PYTHON), "-c", "import rclpy.serialization, geometry_msgs.msg, nav_msgs.msg"],
                           capture_output=True, env={"PATH": "/usr/bin:/bin"})
    if probe.returncode != 0:
        return f"the venv at {REAL_VENV} cannot import rclpy and the message packages"
    return None


def covered_types() -> list[str]:
    """Every message type in the checked-in table (read from the file: no ROS 2 package is imported here)."""
    path = Path(import_roots("ros2")[-1]) / "rosgrade_rosidl" / "_defs.py"
    spec = importlib.util.spec_from_file_location("_rosgrade_ros2_defs_for_tests", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return list(module.MESSAGES)
