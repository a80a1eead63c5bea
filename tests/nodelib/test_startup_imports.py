"""Every node imports the client library before its first line runs: what that pulls in is paid once per node."""
from __future__ import annotations

import json
import os
import subprocess
import sys

from grader.nodelib import precompile, pythonpath

# Modules the ROS 1 library once imported at start-up for one call each (about 20 ms a node together): dataclasses
# brings inspect, ast and dis; hashlib loads OpenSSL.
NOT_AT_START = ("dataclasses", "inspect", "ast", "dis", "hashlib", "_hashlib")

# What a typical course node imports (move_square.py); -S leaves out this machine's .pth files, which are not ours.
NODE_IMPORTS = ("import rosgrade_node.bootstrap, rospy, geometry_msgs.msg, nav_msgs.msg, tf.transformations, "
                "sensor_msgs.msg, std_srvs.srv, turtlesim.msg, turtlesim.srv")


def _modules_after(code: str) -> set[str]:
    precompile()
    env = {k: v for k, v in os.environ.items() if k != "ROSGRADE_CHANNEL"}
    env["PYTHONPATH"] = pythonpath("ros1")
    out = subprocess.run([sys.executable, "-S", "-B", "-c", f"{code}\nimport sys, json\n"
                          "print(json.dumps(sorted(sys.modules)))"],
                         env=env, capture_output=True, text=True, timeout=60, check=True).stdout
    return set(json.loads(out))


def test_a_ros1_node_starts_without_the_modules_it_does_not_need():
    loaded = _modules_after(NODE_IMPORTS)
    assert "rospy" in loaded and "nav_msgs.msg" in loaded  # the imports did happen
    assert not loaded & set(NOT_AT_START), sorted(loaded & set(NOT_AT_START))
