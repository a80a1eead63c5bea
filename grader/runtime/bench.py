"""How fast a node runs under rosgrade: wall time from process start to closed recording, and sim-s per wall-s.

Two nodes stand for the two kinds students write: a 10 Hz `Rate` loop (the course's move_circle) and a busy loop
that publishes with no sleep at all (the Husky tutorial's pattern), where every call costs a sim-time quantum.
"""
from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

from grader.runtime.session import run
from grader.runtime.spec import NodeSpec, RunSpec
from sim import Scenario

RATE_NODE = '''#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist

rospy.init_node("bench_rate")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rate = rospy.Rate(10)
cmd = Twist()
cmd.linear.x, cmd.angular.z = 0.1, 0.2
rospy.on_shutdown(lambda: pub.publish(Twist()))
while not rospy.is_shutdown():
    pub.publish(cmd)
    try:
        rate.sleep()
    except rospy.ROSInterruptException:
        break
'''

BUSY_NODE = '''#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist

rospy.init_node("bench_busy")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
cmd = Twist()
cmd.linear.x = 0.2
while not rospy.is_shutdown():
    pub.publish(cmd)
'''


def time_run(script: Path, sim_seconds: float, out: Path) -> float:
    """Wall seconds for one run: node process start to closed recording (Ctrl+C at the end of the run)."""
    scenario = Scenario(duration=sim_seconds + 1.0, shutdown_at=sim_seconds)
    started = time.perf_counter()
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script),)), out / "bench.mcap", out / "bench.log")
    return time.perf_counter() - started


def runtime_benchmark(move_circle: Path | None = None, sim_seconds: float = 40.0, repeats: int = 5) -> dict:
    """Median and best wall time of `sim_seconds` runs, for move_circle.py (if given) and the two stand-in nodes."""
    figures: dict[str, float | str] = {"sim_seconds": sim_seconds, "repeats": repeats}
    with tempfile.TemporaryDirectory(prefix="rosgrade-bench-") as tmp:
        folder = Path(tmp)
        nodes = {"rate_10hz": folder / "rate.py", "busy_loop": folder / "busy.py"}
        nodes["rate_10hz"].write_text(RATE_NODE)
        nodes["busy_loop"].write_text(BUSY_NODE)
        if move_circle is not None:
            nodes = {"move_circle": move_circle, **nodes}
        for name, script in nodes.items():
            walls = [time_run(script, sim_seconds, folder) for _ in range(repeats)]
            figures[f"{name}_wall_s_median"] = round(statistics.median(walls), 3)
            figures[f"{name}_wall_s_best"] = round(min(walls), 3)
            figures[f"{name}_sim_s_per_wall_s"] = round(sim_seconds / statistics.median(walls), 1)
    return figures


if __name__ == "__main__":
    import json
    import sys

    reference = Path(sys.argv[1]) if len(sys.argv) > 1 else None
    print(json.dumps(runtime_benchmark(reference), indent=2))
