"""Record which publisher/subscription QoS pairs real rclpy (Jazzy, Fast DDS) connects, and the warnings it logs.

Usage: python tests/conformance_ros2/record_qos_matrix.py OUT.json. Two real nodes in two processes on a DDS domain
of their own: one publishes on a topic per (offered, requested) pair at 10 Hz, the other subscribes with the
requested QoS ``lead`` seconds later and counts what arrives. The publishers exist first, as the simulated robot's do
when a student's node starts: a BEST_AVAILABLE policy is resolved against the publishers discovered when the
subscription is created, so the order matters for it. The record holds, per pair, whether anything arrived, and every distinct
"incompatible QoS" warning each side logged (node name and time stripped): what rosgrade's rclpy is compared with.
"""
from __future__ import annotations

import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from real_ros2 import DomainLock, ros2_env, venv_python

NODE = Path(__file__).resolve().parent / "qos_matrix_node.py"
_LOG = re.compile(r"^\[WARN\] \[[0-9.]+\] \[[^\]]+\]: (.*)$")


def _warnings(stderr: str) -> list[str]:
    return sorted({m.group(1) for line in stderr.splitlines() if (m := _LOG.match(line.strip()))})


def _run(role: str, seconds: float, lead: float) -> tuple[dict[str, int], str, str]:
    """(counts per topic, subscriber's stderr, publisher's stderr) of one publisher and one ``role`` subscriber."""
    lock = DomainLock()
    try:
        with tempfile.TemporaryDirectory() as home:
            env = ros2_env(lock.domain_id, Path(home))
            pub = subprocess.Popen([str(venv_python()), str(NODE), "pub", str(seconds + lead)], env=env,
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            time.sleep(lead)
            sub = subprocess.Popen([str(venv_python()), str(NODE), role, str(seconds)], env=env,
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            sub_out, sub_err = sub.communicate(timeout=seconds + 60)
            _, pub_err = pub.communicate(timeout=seconds + 60)
    finally:
        lock.close()
    if not sub_out.strip():
        raise SystemExit(f"the {role} node printed no counts (exit {sub.returncode}); its stderr:\n{sub_err[:1500]}")
    return json.loads(sub_out.strip().splitlines()[-1]), sub_err, pub_err


def record_matrix(seconds: float = 6.0, lead: float = 3.0) -> dict[str, object]:
    """The record: per subscriber role, which pairs received anything and the warnings each side logged."""
    result: dict[str, object] = {
        "source": "rclpy 7.1.6 (ros-jazzy wheels), rmw_fastrtps_cpp; tests/conformance_ros2/qos_matrix_node.py"}
    for role in ("sub", "sub_discovered"):
        counts, sub_err, pub_err = _run(role, seconds, lead)
        result[role] = {"received": {name: count > 0 for name, count in sorted(counts.items())},
                        "subscription_warnings": _warnings(sub_err), "publisher_warnings": _warnings(pub_err)}
    return result


if __name__ == "__main__":
    Path(sys.argv[1]).write_text(json.dumps(record_matrix(), indent=1) + "\n")
