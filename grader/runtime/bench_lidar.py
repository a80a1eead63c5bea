"""What /scan costs a run: CPU per sim-second of the same rospy and rclpy nodes with and without a /scan subscription.

The nodes drive in the arena course world at 10 Hz and, when subscribed, stop turning towards a wall the scan shows
ahead (issue 31 asks that a LiDAR run cost at most 1.3x the run without /scan). Runs alternate (without, with,
without, ...) in one process so that the machine's drift falls on both alike. CPU, the grader's and the node's
together, is the figure load on a shared machine changes least; the world ray-casts /scan only while a node
subscribes to it, so the run without the subscription has no scan work at all.
"""
from __future__ import annotations

import resource
import statistics
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from grader import timing

from grader.recording import Recording
from grader.runtime.session import run
from grader.runtime.spec import NodeSpec, RunSpec
from sim import Scenario

# Prepended to each node: its own CPU seconds, printed as it exits (the grader records the line).
NODE_CPU = """import atexit, resource
def _cpu():
    usage = resource.getrusage(resource.RUSAGE_SELF)
    print("#CPU", usage.ru_utime + usage.ru_stime, flush=True)
atexit.register(_cpu)
"""
ROSPY = NODE_CPU + """import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan
ahead = [9.9]
def on_scan(msg):
    ahead[0] = min(r for r in msg.ranges[:10] + msg.ranges[-10:])
rospy.init_node("drive")
if {scan}:
    rospy.Subscriber("/scan", LaserScan, on_scan)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    cmd = Twist()
    cmd.linear.x = 0.1 if ahead[0] > 0.5 else 0.0
    cmd.angular.z = 0.3
    pub.publish(cmd)
    try:
        rate.sleep()
    except rospy.ROSInterruptException:
        break
"""
RCLPY = NODE_CPU + """import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan


class Drive(Node):
    def __init__(self):
        super().__init__("drive")
        self.ahead = 9.9
        if {scan}:
            self.create_subscription(LaserScan, "scan", self.on_scan, qos_profile_sensor_data)
        self.pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.create_timer(0.1, self.tick)

    def on_scan(self, msg):
        self.ahead = min(list(msg.ranges[:10]) + list(msg.ranges[-10:]))

    def tick(self):
        cmd = TwistStamped()
        cmd.twist.linear.x = 0.1 if self.ahead > 0.5 else 0.0
        cmd.twist.angular.z = 0.3
        self.pub.publish(cmd)


rclpy.init()
try:
    rclpy.spin(Drive())
except KeyboardInterrupt:
    pass
"""
NODES = {"ros1": ROSPY, "ros2": RCLPY}
# The grader's stages (grader.timing) a scan goes through: the sweep, its bytes recorded, its delivery to the node.
SCAN_PATH_STAGES = ("physics and sensors", "world messages (encode, record, queue)",
                    "node steps (channel, node publications)")
SIM_SECONDS = 60.0  # per run: long enough that the node's start-up (imports) weighs little in the ratio
WARM_UP_SIM_SECONDS = 2.0


class LidarBenchError(Exception):
    """A benchmark node did not report its CPU time (it did not exit normally)."""


@dataclass(frozen=True)
class Sample:
    """One run's wall seconds and CPU seconds, the grader's and the node's, and the grader's stage seconds (wall)."""

    wall_s: float
    grader_cpu_s: float
    node_cpu_s: float
    stages: dict[str, float] = field(default_factory=dict)

    @property
    def cpu_s(self) -> float:
        return self.grader_cpu_s + self.node_cpu_s


def _own_cpu_s() -> float:
    """CPU seconds of this process (the grader: world, session, recording), user and system."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    return own.ru_utime + own.ru_stime


def _node_cpu_s(recording: Path) -> float:
    """The CPU seconds the node printed as it exited."""
    lines = [line.text for line in Recording.open(recording).output_lines() if line.text.startswith("#CPU ")]
    if not lines:
        raise LidarBenchError(f"the benchmark node of {recording.name} printed no CPU time: it did not exit normally")
    return float(lines[-1].split()[1])


def time_run(script: Path, flavour: str, sim_seconds: float, out: Path) -> Sample:
    """One run of ``script`` for ``sim_seconds`` in the arena, stopped with Ctrl+C at the end."""
    scenario = Scenario(world="arena", start="south", duration=sim_seconds + 1.0, shutdown_at=sim_seconds)
    with timing.collect() as stages:
        started, cpu = time.perf_counter(), _own_cpu_s()
        run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour=flavour),)), out / "b.mcap",
            out / "b.log")
        wall, grader_cpu = time.perf_counter() - started, _own_cpu_s() - cpu
    return Sample(wall, grader_cpu, _node_cpu_s(out / "b.mcap"), stages)


def summarize(flavour: str, without: list[Sample], with_scan: list[Sample], sim_seconds: float) -> dict[str, float | str]:
    """Best and median CPU ms per sim-second of each, the ratios of medians and of bests, the spread of the
    per-repeat ratios (each run with /scan over the run without it just before), and where the extra CPU goes: the
    grader's and the node's, and the grader's stages a scan goes through (wall time, noisier on a loaded machine)."""
    per_sim_ms = 1000.0 / sim_seconds
    off, on = [s.cpu_s for s in without], [s.cpu_s for s in with_scan]
    pairs = sorted(b / a for a, b in zip(off, on))
    return {
        f"{flavour}_without_scan_cpu_ms_per_sim_s_best": round(min(off) * per_sim_ms, 2),
        f"{flavour}_without_scan_cpu_ms_per_sim_s_median": round(statistics.median(off) * per_sim_ms, 2),
        f"{flavour}_with_scan_cpu_ms_per_sim_s_best": round(min(on) * per_sim_ms, 2),
        f"{flavour}_with_scan_cpu_ms_per_sim_s_median": round(statistics.median(on) * per_sim_ms, 2),
        f"{flavour}_scan_ratio_median": round(statistics.median(on) / statistics.median(off), 3),
        f"{flavour}_scan_ratio_best": round(min(on) / min(off), 3),
        f"{flavour}_scan_ratio_spread": f"{pairs[0]:.3f}-{pairs[-1]:.3f}",
        f"{flavour}_scan_grader_extra_ms_per_sim_s": round(
            (statistics.median(s.grader_cpu_s for s in with_scan)
             - statistics.median(s.grader_cpu_s for s in without)) * per_sim_ms, 2),
        f"{flavour}_scan_node_extra_ms_per_sim_s": round(
            (statistics.median(s.node_cpu_s for s in with_scan)
             - statistics.median(s.node_cpu_s for s in without)) * per_sim_ms, 2),
        **{f"{flavour}_scan_extra_ms_per_sim_s ({name})": round(
            (statistics.median(s.stages.get(name, 0.0) for s in with_scan)
             - statistics.median(s.stages.get(name, 0.0) for s in without)) * per_sim_ms, 2)
           for name in SCAN_PATH_STAGES},
    }


def lidar_benchmark(sim_seconds: float = SIM_SECONDS, repeats: int = 3, flavours: tuple[str, ...] = ("ros1", "ros2")
                    ) -> dict[str, float | str]:
    """The LiDAR cost figures of ``summarize`` for each flavour, from ``repeats`` interleaved pairs of runs."""
    figures: dict[str, float | str] = {"scan_run_sim_seconds": sim_seconds}
    with tempfile.TemporaryDirectory(prefix="rosgrade-lidar-bench-") as tmp:
        folder = Path(tmp)
        for flavour in flavours:
            scripts = {}
            for scan in (False, True):
                scripts[scan] = folder / f"drive_{flavour}_{'scan' if scan else 'blind'}.py"
                scripts[scan].write_text(NODES[flavour].format(scan=scan))
            for scan in (False, True):  # warm-up, not counted: the process's first run imports and compiles more
                time_run(scripts[scan], flavour, WARM_UP_SIM_SECONDS, folder)
            samples: dict[bool, list[Sample]] = {False: [], True: []}
            for _ in range(max(1, repeats)):
                for scan in (False, True):
                    samples[scan].append(time_run(scripts[scan], flavour, sim_seconds, folder))
            figures.update(summarize(flavour, samples[False], samples[True], sim_seconds))
    return figures


if __name__ == "__main__":
    import json
    import sys

    print(json.dumps(lidar_benchmark(*(float(a) for a in sys.argv[1:2]), *(int(a) for a in sys.argv[2:3])),
                     indent=1))
