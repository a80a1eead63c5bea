"""On the real TurtleBot3 base mode a ROS 2 node meets /scan as the robot's LiDAR drivers publish it (ld08_driver and
hls_lfcd_lds_driver: rclcpp::SensorDataQoS, BEST_EFFORT): a RELIABLE subscription (a depth of 10) hears nothing and
logs real rclpy's "offering incompatible QoS" warning, qos_profile_sensor_data hears it; in the simulation (gazebo
mode, RELIABLE) both hear it. The report names the mismatch and the fix, and the topic summary does not count scans
the node's client library dropped."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from grader.recording import Recording
from sim import Scenario
from tests.runtime.test_scan_qos import NODE

pytestmark = pytest.mark.slow

WARNING = ("New publisher discovered on topic '/scan', offering incompatible QoS. No messages will be received from "
           "it. Last incompatible policy: RELIABILITY")
CASES = {  # (base mode, QoS, hears)
    "real_depth": ("real", "10", False),
    "real_sensor_data": ("real", "qos_profile_sensor_data", True),
    "gazebo_depth": ("gazebo", "10", True),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_scan_by_base_mode(tmp_path: Path, case: str) -> None:
    mode, qos, hears = CASES[case]
    script = tmp_path / "listen.py"
    script.write_text(NODE.format(imports="qos_profile_sensor_data", qos=qos, later=False))
    scenario = Scenario(duration=2.0, world="corridor", start="entrance", base_mode=mode)
    result = run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour="ros2"),)), tmp_path / "r.mcap",
                 tmp_path / "r.log")
    recording = Recording.open(tmp_path / "r.mcap")
    printed = [line.text.split() for line in recording.output_lines() if line.text.startswith("scans")]
    warnings = [line.msg for line in recording.rosout() if "incompatible QoS" in line.msg]
    named = [line for line in result.diagnostics if "incompatible" in line]
    received = [line for line in result.topics if "received" in line and "/scan" in line]
    assert printed and len(received) == 1, (printed, result.topics)
    if hears:
        assert int(printed[-1][1]) >= 5 and warnings == [] and named == [], (printed, warnings, named)
        assert "received 0 messages" not in received[0], received
    else:
        assert printed[-1][1] == "0" and warnings == [WARNING], (printed, warnings)
        assert received[0].startswith("listen.py received 0 messages on /scan"), received
        assert len(named) == 1 and "requests RELIABLE" in named[0] and "offers BEST_EFFORT" in named[0], named
        assert "qos_profile_sensor_data" in named[0], named
