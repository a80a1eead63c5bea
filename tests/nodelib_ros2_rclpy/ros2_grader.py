"""The test stand-in grader (tests/nodelib/fake_grader.py) for rclpy probes: ROS 2 import path, CDR deliveries."""
from __future__ import annotations

import os
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

from grader.nodelib import import_roots, pythonpath
from tests.nodelib.fake_grader import FakeGrader, Run

PROBES = Path(__file__).resolve().parent / "probes"
ROS2_PATH = pythonpath("ros2")
# Appended, not prepended: the ROS 1 in-process tests share this process and its message package names
# (geometry_msgs, std_msgs, tf2_ros ...); the names used here in-process (rclpy, rosgrade_rosidl,
# builtin_interfaces) exist only in the ROS 2 root.
sys.path += [str(p) for p in import_roots("ros2") if str(p) not in sys.path]
import rosgrade_rosidl  # noqa: E402


def cdr(msg) -> bytes:
    """A message as the grader delivers it to a ROS 2 node."""
    return rosgrade_rosidl.serialize(msg)


def decode(cls, data: bytes):
    return rosgrade_rosidl.deserialize(cls, data)


@dataclass
class Ros2Grader(FakeGrader):
    """FakeGrader running a probe of this folder with the ROS 2 import roots (use_sim_time comes from args)."""

    params: dict = field(default_factory=dict)
    env: dict = field(default_factory=dict)

    def run(self) -> Run:
        node_r, grader_w = os.pipe()
        grader_r, node_w = os.pipe()
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "ROS_NAMESPACE")}
        env.update(self.env)
        env["PYTHONPATH"] = ROS2_PATH
        env["ROSGRADE_CHANNEL"] = f"{node_r},{node_w}"
        env["PYTHONHASHSEED"] = "0"
        proc = subprocess.Popen([sys.executable, str(PROBES / self.probe), *self.args], env=env,
                                pass_fds=(node_r, node_w), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        os.close(node_r)
        os.close(node_w)
        frames: list = []
        try:
            self._serve(grader_r, grader_w, frames)
        finally:
            os.close(grader_w)
            os.close(grader_r)
            try:
                out, err = proc.communicate(timeout=self.timeout_s)
            except subprocess.TimeoutExpired:
                proc.kill()
                out, err = proc.communicate()
        return Run(frames, proc.returncode, out, err)


SIM = ["--ros-args", "-p", "use_sim_time:=true"]
