"""A node that reads /scan among the scenario's obstacles, run whole: it sees the wall and stops in time; the robot's
sensor topics are recorded at their rates."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

NODES = Path(__file__).parent / "nodes"
WALL = {"kind": "box", "x": 2.0, "y": 0.0, "length": 0.2, "width": 4.0}

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def wall_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("wall")
    spec = RunSpec(scenario=Scenario(duration=15.0, obstacles=[WALL]), nodes=(NodeSpec(script=NODES / "stop_at_wall.py"),))
    result = run(spec, tmp / "run.mcap", tmp / "run.log")
    return result, Recording.open(tmp / "run.mcap")


def test_the_node_stops_short_of_the_wall(wall_run):
    result, rec = wall_run
    assert result.nodes[0].status == "exited" and result.nodes[0].exit_code == 0
    truth = rec.ground_truth()
    # The wall's face is at x = 1.9 and the scanner 6.4 cm behind base_footprint, so "0.5 m ahead" is x = 1.464.
    # A 5 Hz scan sees it up to 4 cm late, the 10 Hz loop reacts up to 2 cm later, and braking at 1 m/s² takes 2 cm.
    assert 1.464 < truth.x[-1] < 1.464 + 0.04 + 0.02 + 0.03
    assert any("stopped 0.4" in text or "stopped 0.5" in text for _, _, text in rec.output_lines())


def test_only_subscribed_sensor_topics_are_published(wall_run):
    result, rec = wall_run
    counts = {t.topic: t.count for t in rec.topics()}
    # /scan at 5 Hz while the node listened: from its subscription until it exited
    stamps = [t_ns for t_ns, _ in rec.world_messages("/scan")]
    gaps = {b - a for a, b in zip(stamps, stamps[1:])}
    assert gaps == {200_000_000} and counts["/scan"] > 10
    assert stamps[-1] / 1e9 <= result.nodes[0].ended_s
    assert "/imu" not in counts and "/joint_states" not in counts  # nobody listened: never produced


def test_a_subscribed_imu_arrives_and_is_recorded_at_its_rate(tmp_path):
    spec = RunSpec(scenario=Scenario(duration=3.0, shutdown_at=2.5),
                   nodes=(NodeSpec(script=NODES / "listen_imu.py"),))
    run(spec, tmp_path / "imu.mcap", tmp_path / "imu.log")
    rec = Recording.open(tmp_path / "imu.mcap")
    counts = {t.topic: t.count for t in rec.topics() if t.origin == "world"}
    # while the node listened (from its subscription until it exited after the Ctrl+C at 2.5 s), at their rates
    imu = [t_ns for t_ns, _ in rec.world_messages("/imu")]
    assert {b - a for a, b in zip(imu, imu[1:])} == {5_000_000} and counts["/imu"] >= 200 * 2.3
    assert counts["/joint_states"] == pytest.approx(counts["/imu"] * 30 / 200, abs=2)
    assert "/scan" not in counts
    printed = [line.text for line in rec.output_lines() if line.text.startswith("received")]
    received_imu = int(printed[0].split()[1])
    assert 0 < received_imu <= counts["/imu"]
