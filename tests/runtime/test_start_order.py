"""Nodes start as `ros2 launch` starts them: with the run, after a TimerAction's delay, or when another node starts or
exits (event handlers), in sim time; nothing starts once launch is shutting down, and a node whose moment never came
is reported as never started."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from grader.runtime.spec import Start
from grader.runtime.start_order import StartOrder
from sim import Scenario

TIMED = Path(__file__).resolve().parent / "nodes" / "starts" / "timed.py"
S = 1_000_000_000


def _specs(*starts: Start) -> list[NodeSpec]:
    return [NodeSpec(script=TIMED, start=start) for start in starts]


def test_a_timer_is_due_its_delay_after_the_start() -> None:
    order = StartOrder(_specs(Start(), Start(delay_s=2.5)), start_ns=10 * S)
    assert order.due(10 * S) == [0] and order.next_ns() == 12_500_000_000
    assert order.due(12 * S) == [] and order.due(13 * S) == [1] and order.next_ns() is None


def test_a_handler_is_due_when_its_node_starts_or_exits_plus_its_delay() -> None:
    order = StartOrder(_specs(Start(), Start(after=0, on="start", delay_s=1.0), Start(after=0, on="exit")), 0)
    assert order.due(0) == [0]
    order.started(0, 0)
    assert order.next_ns() == S
    order.exited(0, 3 * S)
    assert order.due(3 * S) == [1, 2]
    assert order.never_started(3) == [1, 2]  # due is not started: the session says when it has


def test_nothing_starts_once_launch_shuts_down() -> None:
    order = StartOrder(_specs(Start(), Start(delay_s=5.0), Start(after=0)), 0)
    order.due(0)
    order.started(0, 0)
    order.shut_down()
    order.exited(0, S)
    assert order.next_ns() is None and order.due(10 * S) == [] and order.never_started(3) == [1, 2]


def test_a_negative_delay_is_refused() -> None:
    with pytest.raises(ValueError, match="must not be negative"):
        Start(delay_s=-1.0)


@pytest.fixture(scope="module")
def launched(tmp_path_factory: pytest.TempPathFactory) -> tuple[object, Recording, Path]:
    """first runs 1 s; second starts 0.5 s after first exits; third 2 s after the start (TimerAction); never waits
    for a node that outlives the run; Ctrl+C at 6 s."""
    tmp = tmp_path_factory.mktemp("starts")
    nodes = (NodeSpec(script=TIMED, args=("first", "1")),
             NodeSpec(script=TIMED, args=("second", "1"), start=Start(after=0, delay_s=0.5)),
             NodeSpec(script=TIMED, args=("third", "10"), start=Start(delay_s=2.0)),
             NodeSpec(script=TIMED, args=("never", "1"), start=Start(after=2, said="when third exits")))
    result = run(RunSpec(Scenario(duration=8.0, shutdown_at=6.0), nodes), tmp / "run.mcap", tmp / "run.log")
    return result, Recording.open(tmp / "run.mcap"), tmp


def _started(recording: Recording) -> dict[str, float]:
    """When each node logged that it started (sim s; the run starts at 2 s)."""
    return {m.group(1): line.t for line in recording.output_lines()
            if line.stream == "rosout" and (m := re.fullmatch(r"(\w+) started", line.text))}


def test_nodes_start_at_their_timer_or_their_handler_in_sim_time(launched) -> None:
    result, recording, _ = launched
    started = _started(recording)
    # the run starts at 2 s; rospy's init_node takes 0.1 s; first ends 1 s after its first /clock
    assert started["first"] == pytest.approx(2.1, abs=1e-6)
    assert started["second"] == pytest.approx(started["first"] + 1.0 + 0.5 + 0.1, abs=0.03)
    assert started["third"] == pytest.approx(4.1, abs=1e-6)
    assert "never" not in started


def test_a_node_whose_moment_never_came_is_reported_never_started(launched) -> None:
    result, _, _ = launched
    never = result.nodes[3]
    assert never.status == "not_started"
    assert never.message.startswith("never started: launch starts it when third exits")
    assert any("timed.py never started" in note for note in result.diagnostics)
    assert [n.status for n in result.nodes[:3]] == ["exited", "exited", "exited"]  # third ends on Ctrl+C


def test_delayed_starts_repeat_bit_for_bit(launched, tmp_path: Path) -> None:
    _, _, first = launched
    nodes = (NodeSpec(script=TIMED, args=("first", "1")),
             NodeSpec(script=TIMED, args=("second", "1"), start=Start(after=0, delay_s=0.5)),
             NodeSpec(script=TIMED, args=("third", "10"), start=Start(delay_s=2.0)),
             NodeSpec(script=TIMED, args=("never", "1"), start=Start(after=2, said="when third exits")))
    run(RunSpec(Scenario(duration=8.0, shutdown_at=6.0), nodes), tmp_path / "run.mcap", tmp_path / "run.log")
    assert (tmp_path / "run.mcap").read_bytes() == (first / "run.mcap").read_bytes()


@pytest.mark.parametrize("after", [1, 5, -1])
def test_a_node_waiting_for_itself_or_a_node_the_run_lacks_is_refused(after: int) -> None:
    with pytest.raises(ValueError, match="which is not another node of the run"):
        RunSpec(Scenario(), (NodeSpec(script=TIMED), NodeSpec(script=TIMED, start=Start(after=after))))
