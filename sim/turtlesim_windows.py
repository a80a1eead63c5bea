"""Several turtlesim windows in one run, as one world: a launch file that starts turtlesim_node twice (the roslaunch
and ROS 2 launch tutorials' turtlesim_mimic). The first window has turtlesim's own names and is the one graded,
drawn and scripted; each other is a ``TurtlesimWorld`` under its node's name (``sim.scenario.TurtlesimWindow``).

Every window updates on the same 16 ms ticks; their samples are merged in time order, the first window's first at
equal times, so a run is as deterministic as with one window.
"""
from __future__ import annotations

import heapq
from collections.abc import Collection

from sim.samples import Sample, ServiceResult, WorldService, WorldTopic
from sim.scenario import Scenario
from sim.turtlesim import Parameters, Request, TurtlesimError, TurtlesimWorld


def _first(name: str) -> property:
    """What the first window says of ``name``: the run's scenario, clock, node and picture are the first window's."""
    return property(lambda self: getattr(self.first, name), doc=f"the first window's {name}")


class TurtlesimWindows:
    """The run's turtlesim windows behind the world contract (DEVELOPERS.md): what one serves, the run's world serves."""

    def __init__(self, scenario: Scenario, flavour: str = "ros1") -> None:
        self.windows = [TurtlesimWorld(scenario, flavour),
                        *(TurtlesimWorld(scenario, flavour, window) for window in scenario.turtlesim_windows)]
        nodes = [window.node for window in self.windows]
        if len(set(nodes)) < len(nodes):
            raise TurtlesimError(f"two turtlesim windows have one node name: {', '.join(nodes)}")
        self.first = self.windows[0]

    # -- what the first window answers for the run -------------------------------------------------------------------

    scenario = _first("scenario")
    time_ns = _first("time_ns")
    start_ns = _first("start_ns")
    end_ns = _first("end_ns")
    mode_name = _first("mode_name")
    odometry_topic = _first("odometry_topic")
    command_qos = _first("command_qos")
    known_as = _first("known_as")
    node_name = _first("node_name")
    sim_clock = _first("sim_clock")
    canvas = _first("canvas")

    def state(self) -> dict[str, float]:
        return self.first.state()

    # -- what every window adds to ---------------------------------------------------------------------------------

    @property
    def publications(self) -> tuple[WorldTopic, ...]:
        """Every window's topics; one /rosout, which they share."""
        seen: dict[str, WorldTopic] = {}
        for window in self.windows:
            for topic in window.publications:
                seen.setdefault(topic.topic, topic)
        return tuple(seen.values())

    @property
    def command_topics(self) -> tuple[str, ...]:
        return tuple(topic for window in self.windows for topic in window.command_topics)

    @property
    def services(self) -> tuple[WorldService, ...]:
        return tuple(service for window in self.windows for service in window.services)

    def call(self, name: str, request: Request) -> ServiceResult:
        """The request handled by the window that serves ``name``."""
        for window in self.windows:
            if any(service.name == name for service in window.services):
                return window.call(name, request)
        raise TurtlesimError(f"turtlesim serves no service {name!r}")

    def use_parameters(self, params: Parameters) -> None:
        for window in self.windows:
            window.use_parameters(params)

    def command(self, topic: str, linear: tuple[float, float, float] = (0.0, 0.0, 0.0),
                angular: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> bool:
        return any(window.command(topic, linear, angular) for window in self.windows)

    def listen(self, topics: Collection[str] | None) -> None:
        """turtlesim publishes every topic whoever listens."""

    def advance_to(self, t_ns: int) -> list[Sample]:
        """Every window run to ``t_ns``; their samples in time order (the first window's first at equal times)."""
        return list(heapq.merge(*(window.advance_to(t_ns) for window in self.windows), key=lambda s: s.t_ns))

    def next_output_ns(self, topics: Collection[str] | None = None) -> int | None:
        due = [t for window in self.windows if (t := window.next_output_ns(topics)) is not None]
        return min(due, default=None)
