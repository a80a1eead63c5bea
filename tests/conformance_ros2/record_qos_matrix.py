"""Record which publisher/subscription QoS pairs real rclpy (Jazzy, Fast DDS) connects, and the warnings it logs.

Usage: python tests/conformance_ros2/record_qos_matrix.py OUT.json [ROLE ...]. Two real nodes in two processes on a
DDS domain of their own: one publishes on a topic per (offered, requested) pair at 10 Hz, the other subscribes with the
requested QoS ``lead`` seconds later and counts what arrives. The publishers exist first, as the simulated robot's do
when a student's node starts: a BEST_AVAILABLE policy is resolved against the publishers discovered when the
subscription is created, so the order matters for it; ``sub_first`` starts the subscribing node first (two students'
nodes started in the other order). The record holds, per pair, whether anything arrived, and every distinct
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
    """(counts per topic, subscriber's stderr, publisher's stderr) of one publisher and one ``role`` subscriber;
    ``sub_first``: the subscriber's node starts ``lead`` seconds before the publisher's (students' nodes started in
    either order), else the publisher's first."""
    lock = DomainLock()
    try:
        with tempfile.TemporaryDirectory() as home:
            env = ros2_env(lock.domain_id, Path(home))
            sub_role = "sub" if role == "sub_first" else role
            order = [("sub", sub_role), ("pub", "pub")] if role == "sub_first" else [("pub", "pub"), ("sub", sub_role)]
            started = {}
            for index, (side, argument) in enumerate(order):
                if index:
                    time.sleep(lead)
                started[side] = subprocess.Popen(
                    [str(venv_python()), str(NODE), argument, str(seconds + (0 if index else lead))], env=env,
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            pub, sub = started["pub"], started["sub"]
            sub_out, sub_err = sub.communicate(timeout=seconds + 60)
            _, pub_err = pub.communicate(timeout=seconds + 60)
    finally:
        lock.close()
    if not sub_out.strip():
        raise SystemExit(f"the {role} node printed no counts (exit {sub.returncode}); its stderr:\n{sub_err[:1500]}")
    return json.loads(sub_out.strip().splitlines()[-1]), sub_err, pub_err


ROLES = ("sub", "sub_discovered", "sub_first")


def record_matrix(seconds: float = 6.0, lead: float = 3.0, roles: tuple[str, ...] = ROLES) -> dict[str, object]:
    """The record: per subscriber role, which pairs received anything and the warnings each side logged."""
    result: dict[str, object] = {
        "source": "rclpy 7.1.6 (ros-jazzy wheels), rmw_fastrtps_cpp; tests/conformance_ros2/qos_matrix_node.py"}
    for role in roles:
        counts, sub_err, pub_err = _run(role, seconds, lead)
        result[role] = {"received": {name: count > 0 for name, count in sorted(counts.items())},
                        "subscription_warnings": _warnings(sub_err), "publisher_warnings": _warnings(pub_err)}
    return result


if __name__ == "__main__":
    # OUT.json [ROLE ...]: only those roles recorded again, the others kept from OUT.json
    out, again = Path(sys.argv[1]), tuple(sys.argv[2:]) or ROLES
    kept = json.loads(out.read_text()) if out.exists() else {}
    out.write_text(json.dumps({**kept, **record_matrix(roles=again)}, indent=1) + "\n")
