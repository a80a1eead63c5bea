"""One side of the QoS matrix under real rclpy: ``pub`` or ``sub`` on one topic per (offered, requested) pair.

Run by record_qos_matrix.py in the Jazzy venv. ``sub`` creates its subscriptions at once (before discovery, as a
node does in its constructor), ``sub_discovered`` once it has discovered every publisher. Topic ``/qos_<pub>_<sub>`` carries the pair's publisher and
subscription, the publisher offering ``<pub>`` and the subscription requesting ``<sub>`` (reliability and
durability, short keys). The subscriber prints one JSON line: how many messages each topic received.
"""
import itertools
import json
import sys
import time

import rclpy
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

OFFERED = [(r, d) for r in ("reliable", "best_effort", "system_default")
           for d in ("volatile", "transient_local", "system_default")]
REQUESTED = [(r, d) for r in ("reliable", "best_effort", "best_available", "system_default")
             for d in ("volatile", "transient_local", "best_available", "system_default")]


def profile(reliability: str, durability: str) -> QoSProfile:
    return QoSProfile(depth=10, reliability=ReliabilityPolicy[reliability.upper()],
                      durability=DurabilityPolicy[durability.upper()])


def topic(offered: tuple[str, str], requested: tuple[str, str]) -> str:
    return "/qos_" + "_".join(x[:2] + x[-2:] for x in (*offered, *requested))


def wait_for_publishers(node, names: set[str]) -> None:
    """Spin until the graph shows a publisher on every topic in ``names`` (discovery done)."""
    while any(node.count_publishers(name) == 0 for name in names):
        rclpy.spin_once(node, timeout_sec=0.05)


def main(role: str, seconds: float) -> None:
    rclpy.init()
    node = rclpy.create_node(f"qos_{role}")
    pairs = list(itertools.product(OFFERED, REQUESTED))
    counts = {topic(o, r): 0 for o, r in pairs}
    if role == "pub":
        pubs = [node.create_publisher(String, topic(o, r), profile(*o)) for o, r in pairs]
        timer = node.create_timer(0.1, lambda: [p.publish(String(data="x")) for p in pubs])
    else:
        if role == "sub_discovered":
            wait_for_publishers(node, set(counts))

        def counter(name):
            def cb(_msg):
                counts[name] += 1
            return cb
        subs = [node.create_subscription(String, topic(o, r), counter(topic(o, r)), profile(*r)) for o, r in pairs]
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    if role != "pub":
        print(json.dumps(counts), flush=True)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]))
