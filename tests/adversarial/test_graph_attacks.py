"""Hostile graph queries: a node asking the graph without end while another holds hundreds of publishers, and a
forged GRAPH frame. Each ends in a plain verdict in bounded time; the asking costs the node sim time, the grader
a comparison and a send per ask, and a node that never stops sending is stopped when its silence runs out."""
from __future__ import annotations

import dataclasses
import sys
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from adversarial_helpers import CORPUS, LIMITS, assert_nothing_escaped, refuses_to_run_nodes  # noqa: E402

from grader.recording import Recording  # noqa: E402
from grader.runtime import NodeSpec, RunSpec  # noqa: E402
from grader.runtime.node_link import MAX_QUEUED_CREDIT  # noqa: E402
from grader.runtime.session import run  # noqa: E402
from sim import Scenario  # noqa: E402

pytestmark = pytest.mark.slow


@pytest.fixture(autouse=True)
def _no_leftovers():
    if refuses_to_run_nodes():
        pytest.skip("as root without bubblewrap or user namespaces, rosgrade refuses to run nodes")
    yield
    assert_nothing_escaped()


def test_a_node_asking_the_graph_in_a_busy_loop_runs_out_its_sim_time_and_no_more(tmp_path):
    nodes = tuple(NodeSpec(script=CORPUS / f"{name}.py", flavour="ros2")
                  for name in ("graph_endpoint_holder", "graph_query_flood"))
    started = time.monotonic()
    result = run(RunSpec(scenario=Scenario(duration=2.0), nodes=nodes, limits=LIMITS), tmp_path / "run.mcap",
                 tmp_path / "run.log")
    wall = time.monotonic() - started
    assert [n.status for n in result.nodes] == ["stopped_at_end", "stopped_at_end"], result.nodes
    asked = [int(text.split()[1]) for _, stream, text in Recording.open(tmp_path / "run.mcap").output_lines()
             if stream == "stdout" and text.startswith("asked")]
    # every ask charges a library call's quantum (1 ms of sim time): at most a thousand per sim second of the run
    assert asked and max(asked) <= 1000 * 2
    assert wall < LIMITS.wall_s


def _run_one(name: str, tmp: Path, limits=LIMITS):
    return run(RunSpec(scenario=Scenario(duration=2.0), limits=limits,
                       nodes=(NodeSpec(script=CORPUS / f"{name}.py", flavour="ros1"),)), tmp / "run.mcap", tmp / "run.log")


def test_a_graph_query_with_a_payload_is_a_protocol_violation(tmp_path):
    result = _run_one("graph_query_payload", tmp_path)
    assert result.nodes[0].status == "protocol_violation"
    assert result.nodes[0].message == ("the node broke the grader's channel: GRAPH carries 1000 bytes; it asks with "
                                       "none")


def test_raw_graph_frames_without_end_are_stopped_when_the_silence_limit_runs_out(tmp_path):
    # past the node library: no sim time charged and no WAIT, only frames; the watchdog is checked between frames too
    limits = dataclasses.replace(LIMITS, silent_wall_s=1.0)
    started = time.monotonic()
    result = _run_one("graph_raw_flood", tmp_path, limits)
    assert result.nodes[0].status == "timeout"
    assert "did not yield to the grader for 1 s of wall time" in result.nodes[0].message
    # the silence limit, stretched by the node's run-queue wait on a busy machine by at most MAX_QUEUED_CREDIT limits,
    # plus the node's start and stop
    assert time.monotonic() - started < (1 + MAX_QUEUED_CREDIT) * limits.silent_wall_s + 5
