"""With two turtlesim windows the graph has a node for each: an rclpy node lists the second window's node
(/turtlesim2/sim) with its own topics and services, as `ros2 node list` and `ros2 node info` would."""
from __future__ import annotations

from pathlib import Path

from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario
from sim.scenario import TurtlesimWindow

LISTER = """
import rclpy
from rclpy.node import Node
rclpy.init()
node = Node("lister")
end = node.get_clock().now().nanoseconds + 1_500_000_000
while node.get_clock().now().nanoseconds < end:
    rclpy.spin_once(node, timeout_sec=0.1)
print(sorted(node.get_node_names_and_namespaces()))
print(sorted(n for n, _ in node.get_publisher_names_and_types_by_node("sim", "/turtlesim2")))
print(sorted(n for n, _ in node.get_service_names_and_types_by_node("sim", "/turtlesim2") if "spawn" in n))
rclpy.shutdown()
"""


def test_each_turtlesim_window_is_a_node_of_the_graph(tmp_path: Path) -> None:
    script = tmp_path / "lister.py"
    script.write_text(LISTER)
    scenario = Scenario(robot="turtlesim", duration=3.0, turtlesim_windows=[TurtlesimWindow(node="/turtlesim2/sim")])
    result = run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour="ros2"),)), tmp_path / "r.mcap",
                 tmp_path / "r.log")
    assert result.status == "exited", (tmp_path / "r.log").read_text()
    printed = [line.split(" out | ", 1)[1] for line in (tmp_path / "r.log").read_text().splitlines() if " out | " in line]
    assert printed == ["[('lister', '/'), ('sim', '/turtlesim2'), ('turtlesim', '/')]",
                       "['/turtlesim2/turtle1/color_sensor', '/turtlesim2/turtle1/pose']",
                       "['/turtlesim2/spawn']"]
