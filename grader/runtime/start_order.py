"""When each node of a run starts, as `ros2 launch` starts them: with the run, after a TimerAction's delay, or when
another node starts or exits (OnProcessStart / OnProcessExit), all in sim time. Launch starts nothing new once it is
shutting down, so a node still waiting at Ctrl+C never starts."""
from __future__ import annotations

from collections.abc import Sequence

from grader.runtime.spec import NodeSpec, Start


class StartOrder:
    """The run's nodes by start: those due at a time, and those waiting for another node to start or exit."""

    def __init__(self, nodes: Sequence[NodeSpec], start_ns: int) -> None:
        self._starts = [node.start for node in nodes]
        self._due: dict[int, int] = {}  # node index -> when it starts
        self._waiting: set[int] = set()  # node indices waiting for their trigger
        self._started: set[int] = set()
        for index, start in enumerate(self._starts):
            if start.after is None:
                self._due[index] = start_ns + _ns(start.delay_s)
            else:
                self._waiting.add(index)

    def next_ns(self) -> int | None:
        """When the next node is due to start (None: none is, for now)."""
        return min(self._due.values(), default=None)

    def due(self, t_ns: int) -> list[int]:
        """The nodes due to start at ``t_ns``, in the order launch starts them; each is taken off the schedule."""
        ready = sorted((when, index) for index, when in self._due.items() if when <= t_ns)
        for _, index in ready:
            del self._due[index]
        return [index for _, index in ready]

    def started(self, index: int, t_ns: int) -> None:
        """Node ``index`` has started at ``t_ns``: those waiting for its start are due."""
        self._started.add(index)
        self._trigger(index, "start", t_ns)

    def exited(self, index: int, t_ns: int) -> None:
        """Node ``index`` has ended at ``t_ns``: those waiting for its exit are due."""
        self._trigger(index, "exit", t_ns)

    def shut_down(self) -> None:
        """Launch is shutting down (Ctrl+C): nothing more starts."""
        self._due.clear()
        self._waiting.clear()

    def never_started(self, count: int) -> list[int]:
        """Of the run's ``count`` nodes, those that never started."""
        return [index for index in range(count) if index not in self._started]

    def _trigger(self, index: int, event: str, t_ns: int) -> None:
        for waiting in sorted(self._waiting):
            start = self._starts[waiting]
            if start.after == index and start.on == event:
                self._waiting.discard(waiting)
                self._due[waiting] = t_ns + _ns(start.delay_s)


def why_not_started(start: Start, end_s: float) -> str:
    """The outcome message of a node launch would have started later than the run lasted."""
    when = start.said or (f"{start.delay_s:g} s after the start" if start.after is None else "later")
    return f"never started: launch starts it {when}, which had not happened when the run ended at {end_s:.3f} s"


def _ns(seconds: float) -> int:
    return int(round(seconds * 1e9))
