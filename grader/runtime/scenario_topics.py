"""The grader as a publisher: a scenario's publications, each sent as ``rostopic pub`` (ROS 1) or ``ros2 topic pub``
(ROS 2) sends one, under the grader's name (/rosgrade, origin "grader"), routed to node subscribers as a node's are.

What the commands do (rostopic 1.15.15, ros2cli Jazzy, read from their sources):
- ``rostopic pub`` without ``-r`` publishes once, latched, and stays until Ctrl+C; with ``-1`` it leaves 3 s after;
  with ``-r RATE`` it publishes at that rate until Ctrl+C, latched only with ``-l``. Its publisher connects to
  subscribers as any rospy publisher does (after the session's connect delay); what it publishes before is lost.
- ``ros2 topic pub`` publishes at ``-r`` (1 Hz by default) until Ctrl+C; with ``--once`` or ``-t TIMES`` it first
  waits for a matching subscription (checking every 0.1 s), publishes at once, then every period, and leaves 0.1 s
  after its last message. Its QoS is the default profile: reliable, volatile (nothing is kept for late subscribers).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from grader.recording import RecordingError
from grader.runtime.message_values import MessageValueError, build_message
from grader.runtime.node_link import ROBOT, Endpoint, Latched
from grader.runtime.wire import Wire
from sim.scenario import PublicationSpec

CALLER_ID = "/rosgrade"
ONCE_STAY_NS = 3_000_000_000  # rostopic pub -1 stays this long after publishing (its _ONCE_DELAY, 3 s)
POLL_NS = 100_000_000  # ros2 topic pub checks for a matching subscription this often (DEFAULT_WAIT_TIME)
KEEP_ALIVE_NS = 100_000_000  # ros2 topic pub stays this long after its last message (--keep-alive 0.1)
ROS2_TOPIC_PUB_QOS = ("RELIABLE", "VOLATILE")  # ros2 topic pub's default profile (its --qos-* options are not modelled)



class PublicationError(Exception):
    """A scenario publication that cannot be made (unknown type, a field its type does not have, a bad value)."""


class Graph(Protocol):
    """What the publisher needs of the run: who a publisher reaches at t, and the nodes to hand messages to."""

    nodes: list
    discovery_ns: int

    def receivers(self, publisher: Endpoint, t: int) -> list: ...

    def ready_ns(self, publisher: Endpoint) -> int: ...

    def drive(self, publisher: Endpoint, data: bytes, t: int) -> None: ...


@dataclass(frozen=True)
class PlannedPublication:
    """A scenario publication with its message's bytes and the command's schedule, built before the run starts."""

    t_ns: int  # when the command starts, relative to the start
    topic: str
    type: str
    data: bytes
    period_ns: int | None  # None: one message
    times: int  # how many messages (0: until the run ends)
    latch: bool
    wait: bool  # ros2 topic pub --once/-t: wait for a matching subscription before the first message
    stay_ns: int | None  # how long the command stays after its last message (None: until the run ends)
    callerid: str  # /rosgrade; a later command on a topic already published is a node of its own, as in real ROS
    poll_ns: int = POLL_NS  # while waiting: how often the command looks for a matching subscription
    register_ns: int | None = None  # when its publisher registers, relative to the start (None: at t_ns)
    make: Callable[[int], bytes | None] | None = None  # the bytes when they go out (None: ``data``; it: nothing)
    qos: tuple[str, str] | None = None  # ROS 2: (reliability, durability) it offers; None (ROS 1): matches all


def planned_publications(specs: list[PublicationSpec], wire: Wire) -> list[PlannedPublication]:
    """The scenario's publications encoded for the run's wire; PublicationError names one that cannot be made."""
    first = {spec.topic: index for index, spec in reversed(list(enumerate(specs)))}
    return [_planned(index, spec, wire, CALLER_ID if first[spec.topic] == index else f"{CALLER_ID}/pub{index}")
            for index, spec in enumerate(specs)]


def _planned(index: int, spec: PublicationSpec, wire: Wire, callerid: str) -> PlannedPublication:
    where = f"scenario publications[{index}] on {spec.topic}"
    try:
        type_name = wire.canonical(spec.type)
        data = wire.catalog.encode(type_name, build_message(wire, type_name, spec.values))
    except (RecordingError, KeyError) as exc:
        raise PublicationError(f"{where}: {spec.type} is not a message type the run knows ({exc})") from None
    except MessageValueError as exc:
        raise PublicationError(f"{where}: {exc}") from None
    if wire.name == "ros1":
        if spec.times is not None:
            raise PublicationError(f"{where}: rostopic pub has no -t/--times; give once, or a rate (it publishes "
                                   "until the run ends)")
        period = None if spec.rate is None else round(1e9 / spec.rate)
        latch = spec.rate is None or bool(spec.latch)
        stay = ONCE_STAY_NS if spec.once else None
        return PlannedPublication(spec.t_ns, spec.topic, type_name, data, period, 1 if period is None else 0, latch,
                                  False, stay, callerid)
    if spec.latch:
        raise PublicationError(f"{where}: latch is rostopic pub's -l; ros2 topic pub's volatile default is what "
                               "rosgrade models for ROS 2 (remove latch)")
    times = 1 if spec.once else spec.times or 0
    period = round(1e9 / (spec.rate or 1.0))
    return PlannedPublication(spec.t_ns, spec.topic, type_name, data, period, times, False, times != 0,
                              KEEP_ALIVE_NS if times else None, callerid, qos=ROS2_TOPIC_PUB_QOS)


class TopicPublisher:
    """One ``rostopic pub`` / ``ros2 topic pub`` command in the run: its publisher, its schedule and its latch."""

    def __init__(self, planned: PlannedPublication, start_ns: int, graph: Graph,
                 write: Callable[..., None], lost_prefix: str) -> None:
        self._pub = planned
        begin = start_ns + planned.t_ns
        registered = begin if planned.register_ns is None else start_ns + planned.register_ns
        self._endpoint = Endpoint(-1, planned.topic, planned.type, "", None, planned.latch, registered, qos=planned.qos)
        if graph.discovery_ns:  # a new DDS participant: it and the nodes know each other after discovery
            self._endpoint.ready_ns = registered + graph.discovery_ns
        self._graph = graph
        self._write = write
        self._lost_prefix = lost_prefix
        self._due: int | None = begin  # the next message (or, while waiting, the next look for a subscription)
        self._waiting = planned.wait
        self._first: int | None = None
        self._sent = 0
        self._end: int | None = None  # when the command has left the graph
        self._held: Latched | None = None
        self._data = planned.data
        self._now = begin

    def _gone(self, t: int) -> bool:
        return self._end is not None and t >= self._end

    def _reached(self, t: int) -> list:
        """Who the publisher reaches at t: node subscribers (node index, handle) and, on a velocity command topic, the
        robot's base (ROBOT), as ``ros2 topic pub /turtle1/cmd_vel`` drives a turtle."""
        if t < self._endpoint.registered_ns or self._gone(t):
            return []
        return self._graph.receivers(self._endpoint, t)

    def next_ns(self) -> int | None:
        """When the loop must stop for this command (a message due, a latched message to go out or to reach a
        subscriber that has just come); None: nothing more."""
        if self._gone(self._now):
            return None
        times = [] if self._due is None else [self._due]
        held = self._held
        if held is not None:
            if not held.sent:
                times.append(self._graph.ready_ns(self._endpoint))
            elif any(key not in held.receivers for key in self._reached(self._now)):
                times.append(self._now)
        return min(times, default=None)

    def tick(self, t: int) -> None:
        """Publish what is due at t (or look again for a subscription), then serve the latched message."""
        self._now = t
        if self._gone(t):
            return
        if self._due is not None and self._due <= t:
            if self._waiting and not self._reached(t):
                self._due = t + self._pub.poll_ns
            else:
                self._waiting = False
                self._publish(t)
        self._serve_latched(t)

    def _publish(self, t: int) -> None:
        planned = self._pub
        data = planned.data if planned.make is None else planned.make(t)
        if data is None:  # nothing to send after all (a cancel for a goal never sent)
            self._due = None
            return
        self._data = data
        self._first = t if self._first is None else self._first
        self._sent += 1
        more = planned.period_ns is not None and (planned.times == 0 or self._sent < planned.times)
        self._due = self._first + self._sent * planned.period_ns if more else None
        if not more and planned.stay_ns is not None:
            self._end = t + planned.stay_ns
        connected = t >= self._graph.ready_ns(self._endpoint)
        if planned.latch:
            self._held = Latched(data, t, sent=connected, receivers=set())
        if not connected:
            if not planned.latch:
                self._write(self._lost_prefix + planned.topic, planned.type, data, t,
                            callerid=planned.callerid, origin="grader")
            return
        self._write(planned.topic, planned.type, data, t, callerid=self._pub.callerid, latching=planned.latch,
                    origin="grader")
        for key in self._reached(t):
            self._hand(key, t)

    def _serve_latched(self, t: int) -> None:
        """A held latched message goes out once the publisher connects, and to each subscriber that comes later."""
        held = self._held
        if held is None or t < self._graph.ready_ns(self._endpoint):
            return
        if not held.sent:
            held.sent = True
            self._write(self._pub.topic, self._pub.type, held.data, t, callerid=self._pub.callerid, latching=True,
                        origin="grader")
        for key in self._reached(t):
            if key not in held.receivers:
                self._hand(key, t)

    def _hand(self, key: tuple[int, int] | str, t: int) -> None:
        if key == ROBOT:
            self._graph.drive(self._endpoint, self._data, t)
        else:
            index, ident = key
            node = self._graph.nodes[index]
            node.deliveries.append((ident, self._data, (self._pub.callerid, self._pub.latch)))
            node.link.state.subscribers[ident].count += 1
        if self._held is not None:
            self._held.receivers.add(key)
