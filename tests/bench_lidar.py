"""What /scan costs a run: the same rospy and rclpy nodes driving in the arena with and without a /scan subscription.

Usage: python -m tests.bench_lidar [sim_seconds] [repeats]. Runs alternate (without, with, without, ...) in one
process so that the machine's drift falls on both alike; prints the median wall and CPU seconds (the grader's and
the node's) of each and their ratios (issue 31 asks for at most 1.3). The world ray-casts /scan only while a node
subscribes to it.
"""
from __future__ import annotations

import json
import resource
import statistics
import sys
import tempfile
import time
from pathlib import Path

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
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
    rate.sleep()
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
rclpy.spin(Drive())
"""


def _cpu_s() -> float:
    """CPU seconds of this process (the grader: world, session, recording), user and system."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    return own.ru_utime + own.ru_stime


def _node_cpu_s(recording: Path) -> float:
    """The CPU seconds the node printed as it exited."""
    lines = [line.text for line in Recording.open(recording).output_lines() if line.text.startswith("#CPU ")]
    if not lines:
        raise SystemExit(f"the node in {recording} printed no #CPU line: it did not exit normally")
    return float(lines[-1].split()[1])


def _time(script: Path, flavour: str, sim_seconds: float, out: Path) -> tuple[float, float]:
    """(wall, CPU) seconds of one run, CPU the grader's and the node's together: the figure load on a shared machine
    changes least."""
    scenario = Scenario(world="arena", start="south", duration=sim_seconds + 1.0, shutdown_at=sim_seconds)
    started, cpu = time.perf_counter(), _cpu_s()
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour=flavour),)), out / "b.mcap", out / "b.log")
    wall, grader_cpu = time.perf_counter() - started, _cpu_s() - cpu
    return wall, grader_cpu + _node_cpu_s(out / "b.mcap")


def lidar_cost(sim_seconds: float = 40.0, repeats: int = 3) -> dict[str, float]:
    """Median wall and CPU seconds with and without /scan, and their ratios, for rospy and rclpy."""
    figures: dict[str, float] = {"sim_seconds": sim_seconds, "repeats": repeats}
    with tempfile.TemporaryDirectory(prefix="rosgrade-lidar-bench-") as tmp:
        folder = Path(tmp)
        for flavour, source in (("ros1", ROSPY), ("ros2", RCLPY)):
            walls: dict[bool, list[tuple[float, float]]] = {False: [], True: []}
            scripts = {}
            for scan in (False, True):
                scripts[scan] = folder / f"drive_{flavour}_{scan}.py"
                scripts[scan].write_text(source.format(scan=scan))
            for _ in range(repeats):
                for scan in (False, True):
                    walls[scan].append(_time(scripts[scan], flavour, sim_seconds, folder))
            for index, kind in enumerate(("wall", "cpu")):
                without = statistics.median(sample[index] for sample in walls[False])
                with_scan = statistics.median(sample[index] for sample in walls[True])
                figures[f"{flavour}_without_scan_{kind}_s"] = round(without, 3)
                figures[f"{flavour}_with_scan_{kind}_s"] = round(with_scan, 3)
                figures[f"{flavour}_{kind}_ratio"] = round(with_scan / without, 3)
    return figures


if __name__ == "__main__":
    print(json.dumps(lidar_cost(*(float(a) for a in sys.argv[1:2]), *(int(a) for a in sys.argv[2:3])), indent=1))
