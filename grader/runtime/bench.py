"""How fast a node runs under rosgrade: wall time from process start to closed recording, and sim-s per wall-s.

Two rospy nodes stand for the two kinds students write: a 10 Hz `Rate` loop (the course's move_circle) and a busy
loop that publishes with no sleep at all (the Husky tutorial's pattern), where every call costs a sim-time quantum.
Their rclpy counterparts (the ROS 2 course's timer-driven move_circle, and spin_once in a loop) are timed beside
them, with the ROS 2 / ROS 1 wall-time ratio; then what /scan costs a run (`bench_lidar`).
"""
from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

from grader.runtime.bench_lidar import lidar_benchmark
from grader.runtime.client_library import client_library
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


RATE_NODE_ROS2 = '''import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class Rate(Node):
    def __init__(self):
        super().__init__("bench_rate")
        self.pub = self.create_publisher(TwistStamped, "/cmd_vel", 10)
        self.create_timer(0.1, self.tick)

    def tick(self):
        cmd = TwistStamped()
        cmd.header.stamp = self.get_clock().now().to_msg()
        cmd.twist.linear.x, cmd.twist.angular.z = 0.1, 0.2
        self.pub.publish(cmd)


rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
node = Rate()
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    node.pub.publish(TwistStamped())
finally:
    node.destroy_node()
    rclpy.shutdown()
'''

BUSY_NODE_ROS2 = '''import rclpy
from geometry_msgs.msg import TwistStamped

rclpy.init()
node = rclpy.create_node("bench_busy")
pub = node.create_publisher(TwistStamped, "/cmd_vel", 10)
cmd = TwistStamped()
cmd.twist.linear.x = 0.2
try:
    while rclpy.ok():
        pub.publish(cmd)
        rclpy.spin_once(node, timeout_sec=0)
except KeyboardInterrupt:
    pass
'''


def time_run(script: Path, sim_seconds: float, out: Path) -> float:
    """Wall seconds for one run: node process start to closed recording (Ctrl+C at the end of the run)."""
    scenario = Scenario(duration=sim_seconds + 1.0, shutdown_at=sim_seconds)
    node = NodeSpec(script=script, flavour=client_library(script))
    started = time.perf_counter()
    run(RunSpec(scenario=scenario, nodes=(node,)), out / "bench.mcap", out / "bench.log")
    return time.perf_counter() - started


def runtime_benchmark(move_circle: Path | None = None, sim_seconds: float = 40.0, repeats: int = 5,
                      move_circle_ros2: Path | None = None) -> dict:
    """Median and best wall time of `sim_seconds` runs, for the move_circle references (if given) and the stand-in
    nodes, in rospy and rclpy, each rclpy node's median over its rospy counterpart's, and the LiDAR cost figures."""
    figures: dict[str, float | str] = {"sim_seconds": sim_seconds, "repeats": repeats}
    with tempfile.TemporaryDirectory(prefix="rosgrade-bench-") as tmp:
        folder = Path(tmp)
        nodes: dict[str, Path] = {}
        if move_circle is not None:
            nodes["move_circle"] = move_circle
        if move_circle_ros2 is not None:
            nodes["move_circle_ros2"] = move_circle_ros2
        for name, source in (("rate_10hz", RATE_NODE), ("busy_loop", BUSY_NODE), ("rate_10hz_ros2", RATE_NODE_ROS2),
                             ("busy_loop_ros2", BUSY_NODE_ROS2)):
            nodes[name] = folder / f"{name}.py"
            nodes[name].write_text(source)
        medians = {}
        for name, script in nodes.items():
            walls = [time_run(script, sim_seconds, folder) for _ in range(repeats)]
            medians[name] = statistics.median(walls)
            figures[f"{name}_wall_s_median"] = round(medians[name], 3)
            figures[f"{name}_wall_s_best"] = round(min(walls), 3)
            figures[f"{name}_sim_s_per_wall_s"] = round(sim_seconds / medians[name], 1)
        for name in [n for n in medians if n.endswith("_ros2") and n[:-5] in medians]:
            figures[f"{name}_over_ros1"] = round(medians[name] / medians[name[:-5]], 2)
    figures.update(lidar_benchmark(repeats=repeats))
    return figures


if __name__ == "__main__":
    import json
    import sys

    reference = Path(sys.argv[1]) if len(sys.argv) > 1 else None
    print(json.dumps(runtime_benchmark(reference), indent=2))
