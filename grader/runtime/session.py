"""The lockstep loop: advance the world only while every node waits, deliver what is due, record everything.

A node runs only between the grader's BATCH and its own WAIT, and the world moves only while all nodes wait,
so the recording depends on nothing but the node's code and the scenario: the machine's load cannot change it.
"""
from __future__ import annotations

import json
import os
import shutil
import signal
import tempfile
import time
import dataclasses
from collections.abc import Iterator
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import TextIO

import mujoco

from grader import __version__, timing
from grader.nodelib.common import rosgrade_channel as ch
from grader.recording import Recorder
from grader.runtime import confine
from grader.runtime.cpu_claim import one_cpu
from grader.runtime.lookahead import Lookahead, Pace, Speculation
from grader.runtime.diagnostics import diagnose, topic_summary
from grader.runtime.graph import for_session as graph_view
from grader.runtime.node_link import (ROBOT, Endpoint, EndpointLimitExceeded, GraphQuery, Latched, LogLine, NodeExited,
                                      NodeLink, NodeOverLimit, NodeSilent, OutputLine, ParamChange, ProtocolViolation,
                                      Publication, ServiceAnswer, ServiceCall, ServiceOffer, ServiceReply)
from grader.runtime.param_server import GRADER, PARAM_TOPIC, WORLD, ParamServer, initial_tree
from grader.runtime.process import NodeProcess, ProcessError
from grader.runtime.qos_match import connects, news, robot_hears
from grader.runtime.scenario_participant import ParticipantError, ScenarioParticipant, plan
from grader.runtime.services import Caller, ServiceRouter
from grader.runtime.spec import NodeOutcome, NodeSpec, RunResult, RunSpec
from grader.runtime.start_order import StartOrder, why_not_started
from grader.runtime.verdicts import OutputLimitExceeded, exit_status, refine
from grader.runtime.wire import wire_for
from sim import WORLD_NODE_NAMES, AnyWorld, CommandSample, WorldTopic, open_world
from sim.worlds import command_types

# Real rospy connects a new publisher to its subscribers 49-91 ms after it is created (measured); messages
# published before that are lost. A new subscriber to a running publisher (Gazebo's /odom) gets the next message.
CONNECT_DELAY_NS = 50_000_000
# ...unless the node is in a busy loop then: rospy's threads that answer the subscriber (requestTopic, the TCPROS
# header) wait for the GIL. Real rospy 1.15.15, busy from the Publisher on: 0.03-0.16 s, median 0.10 s (13 runs).
BUSY_CONNECT_DELAY_NS = 100_000_000
# Publications that never reached a subscriber are recorded under this prefix, apart from what the robot received.
LOST_PREFIX = "/rosgrade/lost"
# A node's publications on a topic only the world or the grader publish are recorded under this prefix, never
# delivered, and never on the world's own topic.
IGNORED_PREFIX = "/rosgrade/ignored"
DRIVER_CALLERID = "/rosgrade_driver"
# Names of the grader's own nodes (each world's node and real ROS's /rosout): a student node may not take them.
RESERVED_NAMES = frozenset({*WORLD_NODE_NAMES, DRIVER_CALLERID, "/rosout"})
# Wall seconds the runtime waits for a process to go once its channel has closed, before killing it.
EXIT_WAIT_WALL_S = 5.0
WORKROOT_PREFIX = "rosgrade-node-"
# Wall seconds between two looks at what all of a node's processes use together (a /proc walk: not every step).
USAGE_PERIOD_S = 1.0


class RunError(Exception):
    """A run could not be carried out at all (the grader's side failed, not the node)."""


def _ns(seconds: float) -> int:
    return round(seconds * 1e9)


def _s(t_ns: int | None) -> float | None:
    return None if t_ns is None else t_ns / 1e9


@dataclass
class _Node:
    """One node in a session: its process, its channel, and where it is in the lockstep."""

    spec: NodeSpec
    process: NodeProcess
    link: NodeLink
    outcome: NodeOutcome
    alive: bool = True
    wake_ns: int | None = None
    # (handle, bytes) from the world; (handle, bytes, (callerid, latched)) from a node (rosgrade_channel.encode_batch)
    deliveries: list[tuple] = field(default_factory=list)
    # The connection count per topic handle the node was last told (what its get_num_connections() returns).
    told_connections: dict[int, int] = field(default_factory=dict)
    term_ns: int | None = None
    kill_ns: int | None = None
    pace: Pace = field(default_factory=Pace)  # how far the world runs ahead of it (grader/runtime/lookahead)

    @property
    def callerid(self) -> str:
        return self.link.state.name or "/unnamed"

    def listening(self, topic: str, type_name: str) -> Iterator[Endpoint]:
        """The node's open subscribers to ``topic`` with ``type_name``: where a world message on it goes."""
        return (sub for sub in self.link.state.subscribers.values()
                if sub.topic == topic and sub.type == type_name and not sub.closed)


@dataclass(slots=True)
class _Encoded:
    """One message of the world's, ready to record (and to deliver, when ``to_nodes``); slots: a run makes one per
    world message, and a frozen dataclass costs four times as much to build."""

    topic: str
    type: str
    data: bytes
    t_ns: int
    callerid: str
    origin: str
    to_nodes: bool
    seq: int = -1  # the topic's sequence number it took (-1: a scripted command, which takes none)


class Session:
    """One run of one scenario with its nodes; `run()` returns what was observed, the recording holds the rest."""

    def __init__(self, spec: RunSpec, recording: Path, log: Path) -> None:
        self.spec = spec
        self.recording_path = recording
        self.log_path = log
        # One wire flavour per run: the client library of its nodes (rospy: ROS 1, rclpy: ROS 2).
        self.wire = wire_for(spec.flavour, spec.interfaces)
        self.discovery_ns = self.wire.discovery_ns
        self.catalog = self.wire.catalog
        # The velocity command types the robot's base takes (the scenario's choice, else the flavour's robot).
        self.command_types = frozenset(self.wire.canonical(t) for t in command_types(spec.scenario, self.wire.name))
        self.world: AnyWorld | None = None  # built after the node processes start, while they import
        self.start_ns = spec.scenario.start_ns
        self.end_ns = spec.scenario.end_ns
        self.shutdown_ns = spec.scenario.shutdown_ns
        self.shutdown_sent = False
        self.seq: dict[str, int] = {}
        self.nodes: list[_Node] = []
        self.starts = StartOrder(spec.nodes, self.start_ns)  # when each node starts (launch's timers and handlers)
        self.received: dict[str, int] = {}  # command topic -> commands the robot received from nodes
        self.world_topics: set[tuple[str, str]] = set()  # (topic, type) the world publishes, as it publishes
        self.publications: dict[str, WorldTopic] = {}  # what the world declares it publishes, by topic
        self._log_file = None
        self._node_logs: dict[int, TextIO] = {}  # output="log" nodes' own log files, by node index
        self._recorder: Recorder | None = None
        self.params: ParamServer | None = None  # the run's parameter server, from the start of the recording
        self._next_usage_check = 0.0
        self.listened: set[str] | None = None  # the topics the world was last told nodes subscribe to
        # The (type, bytes) of the last command a node's publication gave the robot (None: none, or a scripted one
        # came after it): repeating it changes nothing but the base's timeout.
        self.robot_command: tuple[str, bytes] | None = None
        self.ahead: Speculation | None = None  # the world run ahead of the node now running, until settled
        self.lookahead = Lookahead(self)
        self.services: ServiceRouter | None = None  # who serves what, and the calls in flight (grader/runtime/services)
        self.caller: ScenarioParticipant | None = None  # /rosgrade: the scenario's calls, goals, sets, publications
        try:
            self._plan = plan(spec.scenario, self.wire)
        except ParticipantError as exc:
            raise RunError(str(exc)) from None

    # -- public ------------------------------------------------------------------------------------------------
    def run(self) -> RunResult:
        wall0 = time.monotonic()
        self.recording_path.parent.mkdir(parents=True, exist_ok=True)
        # The nodes' host folders (staged packages; HOME without a sandbox): removed on every path out of the run.
        _remove_stale_workroots()
        workroot = Path(tempfile.mkdtemp(prefix=f"{WORKROOT_PREFIX}{os.getpid()}-"))
        try:
            return self._run_in(workroot, wall0)
        finally:
            shutil.rmtree(workroot, ignore_errors=True)

    def _run_in(self, workroot: Path, wall0: float) -> RunResult:
        try:
            with timing.stage("node start-up", absorb=True):
                for index, node_spec in enumerate(self.spec.nodes):
                    self._spawn(node_spec, workroot / f"node{index}")
            with timing.stage("world set-up (model, run to the start)"):
                self.world = open_world(self.spec.scenario, self.wire.name)
            self._take_declarations()
        except BaseException:
            for node in self.nodes:
                node.process.close()
            raise
        with Recorder(self.recording_path, metadata={"rosgrade": self._world_metadata()},
                      catalog=self.catalog) as rec, \
                open(self.log_path, "w", encoding="utf-8") as log_file:
            self._recorder, self._log_file = rec, log_file
            self._start_parameters()
            self.services = ServiceRouter(self.wire, self.world, rec.write,
                                          lambda index, item: self.nodes[index].deliveries.append(item),
                                          self._world_sample, self._take_declarations)
            self.caller = ScenarioParticipant(self._plan, self.start_ns, self.services, self.params, self, rec.write,
                                              LOST_PREFIX)
            self.graph = graph_view(self, self._plan)  # what GRAPH answers (grader/runtime/graph.py)
            try:
                with timing.stage("node start-up", absorb=True):
                    self._start_due(self.world.time_ns)
                self._loop(wall0)
            finally:
                with timing.stage("stopping nodes"):
                    for node in self.nodes:
                        if node.alive:
                            self._stop(node, "stopped_at_end",
                                       "still running when the scenario ended; stopped by the grader")
                        node.process.close()
                    for index in self.starts.never_started(len(self.nodes)):
                        outcome = self.nodes[index].outcome
                        outcome.status = "not_started"
                        outcome.message = why_not_started(self.spec.nodes[index].start, self.world.time_ns / 1e9)
                for node_log in self._node_logs.values():
                    node_log.close()
            diagnostics = diagnose(self)
            result = RunResult(
                recording=self.recording_path, log=self.log_path, started_s=self.start_ns / 1e9,
                ended_s=self.world.time_ns / 1e9,
                shutdown_requested_s=_s(self.shutdown_ns) if self.shutdown_sent else None,
                nodes=[n.outcome for n in self.nodes], diagnostics=diagnostics, topics=topic_summary(self),
                wall_s=time.monotonic() - wall0, isolation=confine.detect().isolation)
            rec.add_metadata("rosgrade.run", self._run_metadata(result))
        timing.count("runs")
        timing.count("simulated milliseconds", (self.world.time_ns - self.start_ns) // 1_000_000)
        return result

    # -- starting and stopping nodes ---------------------------------------------------------------------------
    def _spawn(self, node_spec: NodeSpec, workdir: Path) -> None:
        raw = self.log_path.with_suffix(f".raw{len(self.nodes)}.log")
        try:
            process = NodeProcess(node_spec, workdir, raw, self.spec.limits)
        except ProcessError as exc:
            raise RunError(str(exc)) from None
        link = NodeLink(process.read_fd, process.write_fd, self.catalog, self.spec.limits.silent_wall_s,
                        self.spec.limits.output_bytes, RESERVED_NAMES, process.over_limit, USAGE_PERIOD_S,
                        process.queued_s)
        # Every process starts with the run (it waits for START); a node runs from its start (StartOrder) on.
        self.nodes.append(_Node(node_spec, process, link,
                                NodeOutcome(script=node_spec.script.name, findings=list(process.notes)), alive=False))

    def _start_due(self, t: int) -> None:
        """Start the nodes due at t (their START, then their first step), unless launch is shutting down."""
        for index in self.starts.due(t):
            self._handshake(self.nodes[index])

    def _handshake(self, node: _Node) -> None:
        link, node_spec = node.link, node.spec
        t = self.world.time_ns
        node.alive = True
        self.starts.started(self.nodes.index(node), t)
        try:
            link.handshake({"t_ns": t, "params": self._start_params(node_spec),
                            "ros_namespace": node_spec.ros_namespace or "", "wall_epoch": _wall_epoch(t),
                            "world_topics": sorted([topic, type_name] for topic, type_name in self.world_topics),
                            "world_qos": {p.topic: list(p.qos) for p in self.publications.values() if p.to_nodes},
                            "interfaces": self.spec.interfaces.payload if self.spec.interfaces else None})
        except (NodeExited, NodeSilent, NodeOverLimit, ProtocolViolation) as exc:
            self._node_failed(node, exc, t)
            return
        self.params.joined(self.nodes.index(node))
        self._step(node, t, first=True)

    def _stop(self, node: _Node, status: str, message: str) -> None:
        node.process.signal_group(signal.SIGKILL)
        code = node.process.wait(EXIT_WAIT_WALL_S)
        self._ended(node, status, message, code)

    def _ended(self, node: _Node, status: str, message: str, code: int | None) -> None:
        node.alive = False
        status, message = refine(status, message, code, node.link.state, node.process, self.spec.limits,
                                 node.outcome.findings)
        if node.link.state.init_ns is None:
            # Python itself (or the sandbox) may have said why on stderr before any rospy call.
            for line in node.link.flush_output():
                self._output(node, line, self.world.time_ns)
            said = " | ".join(node.link.state.stderr_tail) or _tail(node.process.raw_path)
            if said:
                message = f"{message}; before any rospy call it printed: {said}"
        node.outcome.status, node.outcome.message = status, message
        self.services.node_ended(self.nodes.index(node), self.world.time_ns)
        self.starts.exited(self.nodes.index(node), self.world.time_ns)
        if code is not None:
            node.outcome.exit_code = code if code >= 0 else None
            node.outcome.exit_signal = -code if code < 0 else None
        node.outcome.name = node.link.state.name
        node.outcome.ended_s = self.world.time_ns / 1e9
        node.outcome.exception = node.link.state.exception
        for line in node.link.flush_output():
            self._output(node, line, self.world.time_ns)
        if node.spec.required and status != "stopped_at_end" and not self.shutdown_sent:
            # roslaunch: "REQUIRED process has died! Initiating shutdown!" -- every other node gets Ctrl+C now.
            self.shutdown_ns = self.world.time_ns
            node.outcome.findings.append(
                f"{node.outcome.name or node.outcome.script} is required=\"true\" and ended at "
                f"{self.world.time_ns / 1e9:.3f} s, so roslaunch shut every other node down (Ctrl+C).")

    def _node_failed(self, node: _Node, exc: Exception, t: int) -> None:
        if isinstance(exc, NodeExited):
            code = node.process.wait(EXIT_WAIT_WALL_S)
            if code is None:
                node.process.signal_group(signal.SIGKILL)
                code = node.process.wait(EXIT_WAIT_WALL_S)
            status, message = exit_status(code)
            self._ended(node, status, message, code)
        elif isinstance(exc, NodeSilent):
            self._stop(node, "timeout", f"the node {exc}; it was stopped (an endless loop outside rospy calls, "
                                        "or a blocking call such as input() with nothing to read)")
        elif isinstance(exc, (NodeOverLimit, OutputLimitExceeded, EndpointLimitExceeded)):
            self._stop(node, "killed_by_limit", str(exc))
        else:
            self._stop(node, "protocol_violation", f"the node broke the grader's channel: {exc}")

    # -- the loop ----------------------------------------------------------------------------------------------
    def _loop(self, wall0: float) -> None:
        limits = self.spec.limits
        while True:
            alive = self._police([n for n in self.nodes if n.alive])
            if time.monotonic() - wall0 > limits.wall_s:
                for node in alive:
                    self._stop(node, "timeout", f"the run exceeded its wall-clock budget of {limits.wall_s:g} s")
                alive = []
            # The world runs to the scenario's end even after every node has gone: a robot left moving is seen moving.
            horizon = self.end_ns
            t = self.world.time_ns
            self._replay_latched(t)
            subscribed = {sub.topic for node in alive for sub in node.link.state.subscribers.values()
                          if not sub.closed}
            if subscribed != self.listened:
                # Sensors publish while someone listens: nobody reads an unsubscribed 200 Hz /imu, it only costs.
                self.listened = subscribed
                self.world.listen(subscribed)
            pending_now = any(n.deliveries for n in alive)
            if pending_now:
                t_next = t
            else:
                # The world stops the loop only for what some node subscribes to; the rest is recorded on the way.
                candidates = [c for c in (horizon, self.world.next_output_ns(subscribed)) if c is not None]
                candidates += self.latched_connect_times(t)
                if (call_ns := self.caller.next_ns()) is not None:
                    candidates.append(max(call_ns, t))
                if (start_ns := self.starts.next_ns()) is not None:
                    candidates.append(max(start_ns, t))
                for node in alive:
                    term = node.term_ns if node.kill_ns is None else None  # SIGTERM already sent: next is SIGKILL
                    candidates += [c for c in (node.wake_ns, term, node.kill_ns) if c is not None]
                if self.shutdown_ns is not None and not self.shutdown_sent and alive:
                    candidates.append(max(self.shutdown_ns, t))
                t_next = min(candidates)
            if t_next > horizon:
                t_next = horizon
            if t_next > t:
                started = time.perf_counter()
                samples = self.world.advance_to(t_next)
                stepped = time.perf_counter()
                for sample in samples:
                    self._world_sample(sample)
                timing.add("physics and sensors", stepped - started)
                timing.add("world messages (encode, record, queue)", time.perf_counter() - stepped)
            if t_next >= horizon:
                return
            self._decide_connections(alive, t_next)
            self.caller.tick(t_next)
            if self.shutdown_ns is not None and t_next >= self.shutdown_ns:
                self.starts.shut_down()  # launch starts nothing new once it is shutting down
            self._start_due(t_next)
            shutdown = None
            if self.shutdown_ns is not None and not self.shutdown_sent and t_next >= self.shutdown_ns and alive:
                self.shutdown_sent = True
                shutdown = "signal-2"
                for node in alive:
                    node.term_ns = t_next + _ns(self.spec.shutdown_grace_s)
            for node in alive:
                if node.kill_ns is not None and t_next >= node.kill_ns:
                    self._stop(node, "killed_after_shutdown",
                               "ignored Ctrl+C and SIGTERM (no rospy.is_shutdown() check?); killed with SIGKILL")
                    continue
                if node.term_ns is not None and node.kill_ns is None and t_next >= node.term_ns:
                    node.process.signal_group(signal.SIGTERM)
                    node.kill_ns = t_next + _ns(1.0)
                    if node.process.wait(0.2) is not None:
                        self._ended(node, *exit_status(node.process.returncode), node.process.returncode)
                        continue
                due = node.wake_ns is not None and node.wake_ns <= t_next
                if due or node.deliveries or shutdown:
                    self._step(node, t_next, shutdown=shutdown)

    def _police(self, alive: list[_Node]) -> list[_Node]:
        """Stop nodes whose processes together are over a limit (each process alone is held by its rlimits)."""
        now = time.monotonic()
        if now < self._next_usage_check:
            return alive
        self._next_usage_check = now + USAGE_PERIOD_S
        for node in alive:
            why = node.process.over_limit()
            if why:
                self._stop(node, "killed_by_limit", why)
        return [n for n in alive if n.alive]

    def _step(self, node: _Node, t: int, shutdown: str | None = None, first: bool = False) -> None:
        """Let one node run at world time t until it yields, handling everything it does on the way."""
        link = node.link
        timing.count("node steps (BATCH frames)")
        with timing.stage("node steps (channel, node publications)"):
            self._run_node(node, link, t, shutdown, first)

    def _run_node(self, node: _Node, link: NodeLink, t: int, shutdown: str | None, first: bool) -> None:
        ahead: Speculation | None = None
        try:
            if not first:
                clock = self.clock_ns(link, t)
                deliveries, node.deliveries = node.deliveries, []
                changes = self._connection_changes(node, t)
                params = self.params.take(self.nodes.index(node))
                if shutdown is None:
                    ahead = self.lookahead.start(node, t)
                link.resume(t, clock, deliveries, shutdown, changes, params,
                            later=ahead.later if ahead is not None else (),
                            until_ns=ahead.until_ns if ahead is not None else None,
                            inert=ahead.inert if ahead is not None else None, qos_events=news(self, node, t))
            self.ahead = ahead
            node.wake_ns = link.run_until_wait(
                t, lambda event: self._node_event(node, event, ahead.now_ns if ahead is not None else t),
                ahead.inert if ahead is not None else None,
                lambda moment: self.lookahead.moment(ahead, moment), lambda: self.lookahead.settle(ahead, exact=True))
            if ahead is not None and not ahead.settled:
                self.lookahead.settle(ahead, exact=False)
        except (NodeExited, NodeSilent, NodeOverLimit, ProtocolViolation, OutputLimitExceeded,
                EndpointLimitExceeded) as exc:
            if ahead is not None and not ahead.settled:
                # where it ended (or broke the channel): the last moment it named
                self.lookahead.settle(ahead, exact=True)
            self._node_failed(node, exc, ahead.now_ns if ahead is not None else t)
        finally:
            self.ahead = None

    def clock_ns(self, link: NodeLink, t: int) -> int:
        """/clock as the node has it at t: the last 10 ms tick (0 until init_node, as before /clock connects; for
        rclpy, until discovery)."""
        init = link.state.init_ns
        return (t // ch.CLOCK_PERIOD_NS) * ch.CLOCK_PERIOD_NS if init is not None and t >= init + self.discovery_ns \
            else 0

    def discovered(self, node: _Node, t: int) -> bool:
        """Whether the node and the others (the world included) know each other at t: rclpy from its DDS discovery
        on, so nothing reaches its subscribers before; rospy always (the master knows it as it registers)."""
        init = node.link.state.init_ns
        return not self.discovery_ns or (init is not None and t >= init + self.discovery_ns)

    # -- what nodes do -----------------------------------------------------------------------------------------
    def _node_event(self, node: _Node, event: object, t: int) -> ServiceReply | bytes | None:
        if isinstance(event, Publication):
            self._publication(node, event.endpoint, event.data, t)
            return None
        index = self.nodes.index(node)
        if isinstance(event, GraphQuery):
            return self.graph.answer(index, t)
        if isinstance(event, ServiceCall):
            return self.services.call(Caller(node.callerid, "node", index, event.ident, event.seq), event, t)
        if isinstance(event, ServiceOffer):
            self.services.offer(index, event.endpoint, lambda: node.callerid, lambda: node.alive, t)
        elif isinstance(event, ServiceAnswer):
            self.services.answer(index, event, t)
        elif isinstance(event, ParamChange):
            if event.value is None:
                self.params.delete(event.name, index)
            else:
                self.params.set(event.name, event.value, index)
        elif isinstance(event, OutputLine):
            self._output(node, event, t)
            if node.link.state.output_truncated:
                raise OutputLimitExceeded(f"printed more than its output limit of {self.spec.limits.output_bytes} "
                                          "bytes; it was stopped")
        elif isinstance(event, LogLine):
            self._recorder.write("/rosout", self.wire.log_type,
                                 self.wire.log(t, self._next_seq("/rosout"), event.level, node.callerid, event.msg,
                                               event.file, event.function, event.line,
                                               sorted({e.topic for e in node.link.state.publishers.values()})),
                                 t, callerid=node.callerid, origin="node")
        return None

    # -- the parameter server (grader/runtime/param_server.py) ----------------------------------------------------
    def _start_parameters(self) -> None:
        """The tree as the task sets it and the world's start makes it (turtlesim sets its defaults), recorded."""
        self.params = ParamServer(initial_tree(self.world.sim_clock, [n.params for n in self.spec.nodes]),
                                  self._record_param)
        use = getattr(self.world, "use_parameters", None)
        if use is not None:
            use(self.params)
        self.params.start()

    def _start_params(self, node_spec: NodeSpec) -> dict:
        """START's parameters (see Wire.start_params)."""
        return self.wire.start_params(self.params.tree, self.world.sim_clock, node_spec.params)

    def _record_param(self, text: str, author: int | str) -> None:
        """One entry of /rosgrade/param, under whoever made the change (a node index, the world or the grader)."""
        if author == WORLD:
            callerid, origin = self.world.node_name, "world"
        elif author == GRADER:
            callerid, origin = "/rosgrade", "grader"
        else:
            callerid, origin = self.nodes[author].callerid, "node"
        self._recorder.write(PARAM_TOPIC, self.wire.string_type, self.wire.string(text), self.world.time_ns,
                             callerid=callerid, origin=origin)

    def _take_declarations(self) -> None:
        """What the world publishes now: at the start, and again after a service call (spawn and kill change it)."""
        canonical = self.wire.canonical
        self.publications = {p.topic: dataclasses.replace(p, type=canonical(p.type)) for p in self.world.publications}
        self.world_topics = {(p.topic, p.type) for p in self.publications.values() if p.to_nodes}

    # -- connections (as a ROS 1 master and TCPROS would make them) -------------------------------------------
    @staticmethod
    def ready_ns(publisher: Endpoint) -> int:
        """When a node's publisher has connected to the subscribers that existed when it registered (at the earliest
        CONNECT_DELAY_NS after, until _decide_connections has decided)."""
        return publisher.ready_ns if publisher.ready_ns is not None else publisher.registered_ns + CONNECT_DELAY_NS

    def _decide_connections(self, alive: list[_Node], t: int) -> None:
        """Fix when publishers connect, before any node runs at t. rclpy: at discovery at the earliest. rospy: once
        CONNECT_DELAY_NS has passed, by what the node was doing then (its last WAIT spans that time): blocked, at
        once; in a busy loop, BUSY_CONNECT_DELAY_NS after it registered."""
        for node in alive:
            init = node.link.state.init_ns
            for pub in node.link.state.publishers.values():
                if pub.ready_ns is not None or pub.closed:
                    continue
                due = pub.registered_ns + CONNECT_DELAY_NS
                if self.discovery_ns:
                    if init is not None:
                        pub.ready_ns = max(due, init + self.discovery_ns)
                elif t >= due:
                    pub.ready_ns = pub.registered_ns + BUSY_CONNECT_DELAY_NS if node.link.state.busy else due

    def receivers(self, publisher: Endpoint, t: int) -> list:
        """Who a node's publisher is connected to at t: the robot's base (ROBOT) and (node index, subscriber handle)
        pairs; a subscriber that registers after the publisher connected is connected at once."""
        if t < self.ready_ns(publisher):
            return []
        found: list = []
        if robot_hears(publisher, self):
            found.append(ROBOT)
        for index, other in enumerate(self.nodes):
            if other.alive and self.discovered(other, t):
                found += [(index, sub.ident) for sub in other.link.state.subscribers.values()
                          if sub.topic == publisher.topic and sub.type == publisher.type and not sub.closed
                          and t >= sub.registered_ns and connects(publisher, sub)]
        return found

    def _publishers_of(self, node: _Node, subscriber: Endpoint, t: int) -> set:
        """The peers (the world, or node indexes) whose publishers a node's subscriber is connected to at t."""
        if not self.discovered(node, t):
            return set()
        peers: set = {ROBOT} if (subscriber.topic, subscriber.type) in self.world_topics else set()
        for index, other in enumerate(self.nodes):
            if other.alive and any(pub.topic == subscriber.topic and pub.type == subscriber.type and not pub.closed
                                   and t >= max(self.ready_ns(pub), subscriber.registered_ns)
                                   and connects(pub, subscriber) for pub in other.link.state.publishers.values()):
                peers.add(index)
        return peers

    def _connection_changes(self, node: _Node, t: int) -> dict[int, int]:
        """The node's connection counts at t that differ from what it was last told (one per peer node, as the
        connections of real rospy are per node, not per Subscriber object)."""
        counts = {}
        for pub in node.link.state.publishers.values():
            if not pub.closed:
                counts[pub.ident] = len({key if key == ROBOT else key[0] for key in self.receivers(pub, t)})
        for sub in node.link.state.subscribers.values():
            if not sub.closed:
                counts[sub.ident] = len(self._publishers_of(node, sub, t))
        changes = {ident: n for ident, n in counts.items() if node.told_connections.get(ident, 0) != n}
        node.told_connections.update(changes)
        return changes

    def _route(self, node: _Node, publisher: Endpoint, data: bytes, t: int) -> None:
        """Hand a node's publication to everything connected to its publisher at t."""
        for key in self.receivers(publisher, t):
            self._hand_over(key, node, publisher, data, t)
            if publisher.latched is not None:
                publisher.latched.receivers.add(key)

    def drive(self, publisher: Endpoint, data: bytes, t: int) -> None:
        """A velocity command reaches the robot's base at t (from a node, or the scenario's ``topic pub``)."""
        if self.ahead is not None:  # the command in force, repeated (see Lookahead._inert)
            self.ahead.renewed_ns = t
        else:
            linear, angular = self.wire.decode_command(publisher.type, data)
            self.world.command(publisher.topic, linear=linear, angular=angular)
        self.robot_command = (publisher.type, data)

    def _hand_over(self, key, node: _Node, publisher: Endpoint, data: bytes, t: int) -> None:
        if key == ROBOT:
            self.drive(publisher, data, t)
            self.received[publisher.topic] = self.received.get(publisher.topic, 0) + 1
        else:
            index, ident = key
            self.nodes[index].deliveries.append((ident, data, (node.callerid, publisher.latch)))
            self.nodes[index].link.state.subscribers[ident].count += 1

    def _replay_latched(self, t: int) -> None:
        """A latched publisher's last message goes out when the publisher connects (recorded on its topic then,
        if it was published before), and again to each subscriber that connects later, as real rospy does."""
        for node in self.nodes:
            if not node.alive:
                continue
            for pub in node.link.state.publishers.values():
                held = pub.latched
                if held is None or pub.closed or t < self.ready_ns(pub):
                    continue
                if not held.sent:
                    held.sent = True
                    self._recorder.write(pub.topic, pub.type, held.data, t, callerid=node.callerid, latching=True,
                                         origin="node")
                for key in self.receivers(pub, t):
                    if key not in held.receivers:
                        held.receivers.add(key)
                        self._hand_over(key, node, pub, held.data, t)

    def latched_connect_times(self, t: int) -> list[int]:
        """Future times at which a held latched message goes out (its publisher connects)."""
        return [self.ready_ns(pub) for node in self.nodes if node.alive
                for pub in node.link.state.publishers.values()
                if pub.latched is not None and not pub.closed and self.ready_ns(pub) > t]

    def _publication(self, node: _Node, endpoint: Endpoint, data: bytes, t: int) -> None:
        if self.ignored(endpoint):
            # only the world and the grader speak here
            note = (f"{node.outcome.script} published on {endpoint.topic}, which only the simulated robot and the "
                    "grader publish; those messages were ignored.")
            if note not in node.outcome.findings:
                node.outcome.findings.append(note)
            self._recorder.write(IGNORED_PREFIX + endpoint.topic, endpoint.type, data, t, callerid=node.callerid,
                                 origin="node")
            return
        connected = t >= self.ready_ns(endpoint)
        if endpoint.latch:
            held = endpoint.latched
            if held is not None and not held.sent:  # replaced before it could go out: that one is lost
                self._lost(node, endpoint, held.data, held.t_ns)
            endpoint.latched = Latched(data, t, sent=connected)
            if not connected:
                return
        if not connected:
            self._lost(node, endpoint, data, t)
            return
        self._recorder.write(endpoint.topic, endpoint.type, data, t, callerid=node.callerid, latching=endpoint.latch,
                             origin="node")
        self._route(node, endpoint, data, t)

    def ignored(self, publisher: Endpoint) -> bool:
        """Whether a node's publisher is on a topic only the world or the grader publish (its messages are ignored)."""
        topic = publisher.topic
        world_only = topic in self.publications and not self.publications[topic].shared
        return world_only or topic == "/clock" or topic.startswith("/rosgrade/")

    def _lost(self, node: _Node, endpoint: Endpoint, data: bytes, t: int) -> None:
        endpoint.dropped_before_connect += 1
        self._recorder.write(LOST_PREFIX + endpoint.topic, endpoint.type, data, t, callerid=node.callerid,
                             origin="node")

    def _output(self, node: _Node, line: OutputLine, t: int) -> None:
        topic = "/rosgrade/stdout" if line.stream == 1 else "/rosgrade/stderr"
        self._recorder.write(topic, self.wire.string_type, self.wire.string(line.text), t, callerid=node.callerid,
                             origin="node")
        self._text_log(node).write(f"[{t / 1e9:12.6f}] {'out' if line.stream == 1 else 'err'} | {line.text}\n")

    def _text_log(self, node: _Node) -> TextIO:
        """Where a node's text goes: the run's log ("screen"), or a file of its own (output="log")."""
        if node.spec.output == "screen":
            return self._log_file
        index = self.nodes.index(node)
        if index not in self._node_logs:
            path = node_log_path(self.log_path, index)
            self._node_logs[index] = open(path, "w", encoding="utf-8")  # noqa: SIM115 -- closed at the end of run()
        return self._node_logs[index]

    # -- what the world does -----------------------------------------------------------------------------------
    def _next_seq(self, topic: str) -> int:
        seq = self.seq.get(topic, 0)
        self.seq[topic] = seq + 1
        return seq

    def _world_sample(self, sample: object) -> None:
        """Record one thing the world did; deliver it to subscribers when its topic is declared for nodes."""
        self.commit(self.encode(sample), queue=True)

    def encode(self, sample: object) -> _Encoded:
        """A world sample as the message recorded (a scripted driver's command is recorded as the grader's)."""
        if isinstance(sample, CommandSample):
            return _Encoded(sample.topic, self.wire.twist_type, self.wire.twist(sample.linear, sample.angular),
                            sample.t_ns, DRIVER_CALLERID, "grader", False)
        publication = self.publications[sample.topic]
        seq = self._next_seq(sample.topic)
        return _Encoded(sample.topic, publication.type, self.wire.encode(sample, seq), sample.t_ns,
                        publication.node or self.world.node_name, "world", publication.to_nodes, seq)

    def commit(self, item: _Encoded, queue: bool) -> None:
        """Record a world message and count it for its subscribers, queueing it for their next batch if ``queue``
        (a later moment's deliveries went out in the batch already)."""
        self._recorder.write(item.topic, item.type, item.data, item.t_ns, callerid=item.callerid, origin=item.origin)
        if item.seq < 0:  # a scripted command: the base now has another command than any node's
            self.robot_command = None
        if item.to_nodes:
            self._deliver(item.topic, item.type, item.data, item.t_ns, queue)

    def _deliver(self, topic: str, type_name: str, data: bytes, t: int, queue: bool = True) -> None:
        """Queue a message the world publishes at t for every live subscriber of its topic and type that hears the
        world (next batch)."""
        self.world_topics.add((topic, type_name))
        for node in self.nodes:
            if not node.alive or not self.discovered(node, t):
                continue
            for sub in node.listening(topic, type_name):
                if queue:
                    node.deliveries.append((sub.ident, data))
                sub.count += 1

    # -- metadata ----------------------------------------------------------------------------------------------
    def _world_metadata(self) -> dict[str, str]:
        scenario = self.spec.scenario
        return {
            "rosgrade_version": __version__,
            "mujoco_version": mujoco.__version__,
            "robot": scenario.robot,
            "base_mode": self.world.mode_name,
            "odometry_topic": self.world.odometry_topic,
            "command_topics": json.dumps(list(self.world.command_topics)),
            "command_types": json.dumps(sorted(self.command_types)),
            "client_library": self.wire.client_library,
            "scenario_name": self.spec.name,
            "scenario": scenario.model_dump_json(),
        }

    def _run_metadata(self, result: RunResult) -> dict[str, str]:
        first = result.nodes[0] if result.nodes else NodeOutcome(script="")
        return {
            "status": result.status,
            "started_s": repr(result.started_s),
            "ended_s": repr(first.ended_s if first.ended_s is not None else result.ended_s),
            "world_ended_s": repr(result.ended_s),
            "shutdown_requested_s": json.dumps(result.shutdown_requested_s),
            "exit_code": json.dumps(first.exit_code),
            "exit_signal": json.dumps(first.exit_signal),
            "nodes": json.dumps([asdict(n) for n in result.nodes]),
            "diagnostics": json.dumps(result.diagnostics),
            "topics": json.dumps(result.topics),
        }


def _tail(path: Path, limit: int = 600) -> str:
    """The last lines a process wrote to its raw output file, on one line."""
    try:
        text = path.read_bytes()[-limit:].decode("utf-8", "replace")
    except OSError:
        return ""
    return " | ".join(line.strip() for line in text.splitlines() if line.strip())


def _wall_epoch(t_ns: int) -> float:
    """A fixed wall-clock epoch for the node's time.time(), so log lines are identical run to run."""
    return 1_700_000_000.0 - t_ns / 1e9


def node_log_path(log: Path, index: int) -> Path:
    """Where the text of the run's node number `index` goes when it has output="log" (beside the run's log)."""
    return log.with_suffix(f".node{index}.log")


def _remove_stale_workroots() -> None:
    """Remove the node folders of graders that were killed (SIGKILL, power loss) before they could."""
    for folder in Path(tempfile.gettempdir()).glob(f"{WORKROOT_PREFIX}*-*"):
        try:
            os.kill(int(folder.name[len(WORKROOT_PREFIX):].split("-")[0]), 0)
        except ProcessLookupError:
            shutil.rmtree(folder, ignore_errors=True)
        except (ValueError, OSError):
            pass  # not ours to judge, or its grader is alive (maybe another user's)


def run(spec: RunSpec, recording: Path, log: Path) -> RunResult:
    """Run the scenario with its nodes, write the recording and the node log, and report what happened."""
    with one_cpu():
        return Session(spec, recording, log).run()
