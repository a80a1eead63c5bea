"""The lockstep loop: advance the world only while every node waits, deliver what is due, record everything.

A node runs only between the grader's RESUME and its own WAIT, and the world moves only while all nodes wait,
so the recording depends on nothing but the node's code and the scenario: the machine's load cannot change it.
"""
from __future__ import annotations

import json
import signal
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

import mujoco

from grader import __version__
from grader.nodelib import rosgrade_channel as ch
from grader.recording import (Recorder, default_catalog, decode_twist, ground_truth_bytes, log_bytes,
                              odometry_bytes, string_bytes, tf_bytes, twist_bytes)
from grader.runtime.diagnostics import diagnose, topic_summary
from grader.runtime.node_link import (Endpoint, LogLine, NodeExited, NodeLink, NodeSilent, OutputLine,
                                      ProtocolViolation, Publication)
from grader.runtime.process import NodeProcess, ProcessError
from grader.runtime.spec import NodeOutcome, NodeSpec, RunResult, RunSpec
from grader.runtime.verdicts import OutputLimitExceeded, exit_status, refine
from sim import CommandSample, GroundTruthSample, OdometrySample, TransformSample, World

# Real rospy connects a new publisher to its subscribers 49-91 ms after it is created (measured); messages
# published before that are lost. A new subscriber to a running publisher (Gazebo's /odom) gets the next message.
CONNECT_DELAY_NS = 50_000_000
# Publications that never reached a subscriber are recorded under this prefix, apart from what the robot received.
LOST_PREFIX = "/rosgrade/lost"
WORLD_CALLERID = "/gazebo"
DRIVER_CALLERID = "/rosgrade_driver"
GROUND_TRUTH_TOPIC = "/ground_truth/odom"
TWIST = "geometry_msgs/Twist"
# Wall seconds the runtime waits for a process to go once its channel has closed, before killing it.
EXIT_WAIT_WALL_S = 5.0


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
    deliveries: list[tuple[int, bytes]] = field(default_factory=list)
    term_ns: int | None = None
    kill_ns: int | None = None

    @property
    def callerid(self) -> str:
        return self.link.state.name or "/unnamed"


class Session:
    """One run of one scenario with its nodes; `run()` returns what was observed, the recording holds the rest."""

    def __init__(self, spec: RunSpec, recording: Path, log: Path) -> None:
        self.spec = spec
        self.recording_path = recording
        self.log_path = log
        self.catalog = default_catalog()
        self.world: World | None = None  # built after the node processes start, while they import
        self.start_ns = spec.scenario.start_ns
        self.end_ns = spec.scenario.end_ns
        self.shutdown_ns = spec.scenario.shutdown_ns
        self.shutdown_sent = False
        self.seq: dict[str, int] = {}
        self.nodes: list[_Node] = []
        self.received: dict[str, int] = {}  # command topic -> commands the robot received from nodes
        self._log_file = None
        self._recorder: Recorder | None = None

    # -- public ------------------------------------------------------------------------------------------------
    def run(self) -> RunResult:
        wall0 = time.monotonic()
        self.recording_path.parent.mkdir(parents=True, exist_ok=True)
        workroot = Path(tempfile.mkdtemp(prefix="rosgrade-node-"))
        try:
            for index, node_spec in enumerate(self.spec.nodes):
                self._spawn(node_spec, workroot / f"node{index}")
            self.world = World(self.spec.scenario)
        except BaseException:
            for node in self.nodes:
                node.process.close()
            raise
        with Recorder(self.recording_path, metadata={"rosgrade": self._world_metadata()}) as rec, \
                open(self.log_path, "w", encoding="utf-8") as log_file:
            self._recorder, self._log_file = rec, log_file
            try:
                for node in list(self.nodes):
                    self._handshake(node)
                self._loop(wall0)
            finally:
                for node in self.nodes:
                    if node.alive:
                        self._stop(node, "stopped_at_end",
                                   "still running when the scenario ended; stopped by the grader")
                    node.process.close()
            diagnostics = diagnose(self)
            result = RunResult(
                recording=self.recording_path, log=self.log_path, started_s=self.start_ns / 1e9,
                ended_s=self.world.time_ns / 1e9,
                shutdown_requested_s=_s(self.shutdown_ns) if self.shutdown_sent else None,
                nodes=[n.outcome for n in self.nodes], diagnostics=diagnostics, topics=topic_summary(self),
                wall_s=time.monotonic() - wall0)
            rec.add_metadata("rosgrade.run", self._run_metadata(result))
        return result

    # -- starting and stopping nodes ---------------------------------------------------------------------------
    def _spawn(self, node_spec: NodeSpec, workdir: Path) -> None:
        raw = self.log_path.with_suffix(f".raw{len(self.nodes)}.log")
        try:
            process = NodeProcess(node_spec, workdir, raw, self.spec.limits)
        except ProcessError as exc:
            raise RunError(str(exc)) from None
        link = NodeLink(process.read_fd, process.write_fd, self.catalog, self.spec.limits.silent_wall_s,
                        self.spec.limits.output_bytes)
        self.nodes.append(_Node(node_spec, process, link,
                                NodeOutcome(script=node_spec.script.name, findings=list(process.notes))))

    def _handshake(self, node: _Node) -> None:
        link, node_spec = node.link, node.spec
        t = self.world.time_ns
        try:
            link.handshake({"t_ns": t, "params": {"/use_sim_time": True, **node_spec.params},
                            "ros_namespace": node_spec.ros_namespace or "", "wall_epoch": _wall_epoch(t),
                            # In its own PID namespace the node's pid is the same on every run.
                            "stable_pid": node.process.plan.sandboxed})
        except (NodeExited, NodeSilent, ProtocolViolation) as exc:
            self._node_failed(node, exc, t)
            return
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
        if code is not None:
            node.outcome.exit_code = code if code >= 0 else None
            node.outcome.exit_signal = -code if code < 0 else None
        node.outcome.name = node.link.state.name
        node.outcome.ended_s = self.world.time_ns / 1e9
        node.outcome.exception = node.link.state.exception
        for line in node.link.flush_output():
            self._output(node, line, self.world.time_ns)

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
        elif isinstance(exc, OutputLimitExceeded):
            self._stop(node, "killed_by_limit", str(exc))
        else:
            self._stop(node, "protocol_violation", f"the node broke the grader's channel: {exc}")

    # -- the loop ----------------------------------------------------------------------------------------------
    def _loop(self, wall0: float) -> None:
        limits = self.spec.limits
        while True:
            alive = [n for n in self.nodes if n.alive]
            if time.monotonic() - wall0 > limits.wall_s:
                for node in alive:
                    self._stop(node, "timeout", f"the run exceeded its wall-clock budget of {limits.wall_s:g} s")
                alive = []
            # The world runs to the scenario's end even after every node has gone: a robot left moving is seen moving.
            horizon = self.end_ns
            t = self.world.time_ns
            pending_now = any(n.deliveries for n in alive)
            if pending_now:
                t_next = t
            else:
                candidates = [horizon, self.world.next_output_ns()]
                for node in alive:
                    term = node.term_ns if node.kill_ns is None else None  # SIGTERM already sent: next is SIGKILL
                    candidates += [c for c in (node.wake_ns, term, node.kill_ns) if c is not None]
                if self.shutdown_ns is not None and not self.shutdown_sent and alive:
                    candidates.append(max(self.shutdown_ns, t))
                t_next = min(candidates)
            if t_next > horizon:
                t_next = horizon
            if t_next > t:
                for sample in self.world.advance_to(t_next):
                    self._world_sample(sample)
            if t_next >= horizon:
                return
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

    def _step(self, node: _Node, t: int, shutdown: str | None = None, first: bool = False) -> None:
        """Let one node run at world time t until it yields, handling everything it does on the way."""
        link = node.link
        try:
            if not first:
                clock = (t // ch.CLOCK_PERIOD_NS) * ch.CLOCK_PERIOD_NS if link.state.init_ns is not None else 0
                deliveries, node.deliveries = node.deliveries, []
                link.resume(t, clock, deliveries, shutdown)
            node.wake_ns = link.run_until_wait(t, lambda event: self._node_event(node, event, t))
        except (NodeExited, NodeSilent, ProtocolViolation, OutputLimitExceeded) as exc:
            self._node_failed(node, exc, t)

    # -- what nodes do -----------------------------------------------------------------------------------------
    def _node_event(self, node: _Node, event: object, t: int) -> None:
        if isinstance(event, Publication):
            self._publication(node, event.endpoint, event.data, t)
        elif isinstance(event, OutputLine):
            self._output(node, event, t)
            if node.link.state.output_truncated:
                raise OutputLimitExceeded(f"printed more than its output limit of {self.spec.limits.output_bytes} "
                                          "bytes; it was stopped")
        elif isinstance(event, LogLine):
            self._recorder.write("/rosout", "rosgraph_msgs/Log",
                                 log_bytes(t, self._next_seq("/rosout"), event.level, node.callerid, event.msg,
                                           event.file, event.function, event.line,
                                           sorted({e.topic for e in node.link.state.publishers.values()})),
                                 t, callerid=node.callerid)

    def _connected(self, node: _Node, endpoint: Endpoint, t: int) -> bool:
        """Whether a publisher created at its registration (or at init_node, if earlier) has connected by t."""
        init_ns = node.link.state.init_ns
        since = max(endpoint.registered_ns, t if init_ns is None else init_ns)
        return t >= since + CONNECT_DELAY_NS

    def _publication(self, node: _Node, endpoint: Endpoint, data: bytes, t: int) -> None:
        if endpoint.topic in (self.world.mode.odometry.topic, GROUND_TRUTH_TOPIC, "/clock", "/rosgrade/stdout",
                              "/rosgrade/stderr"):  # only the world and the grader speak here: not recorded
            note = (f"{node.outcome.script} published on {endpoint.topic}, which only the simulated robot and the "
                    "grader publish; those messages were ignored.")
            if note not in node.outcome.findings:
                node.outcome.findings.append(note)
            return
        if not self._connected(node, endpoint, t):
            endpoint.dropped_before_connect += 1
            self._recorder.write(LOST_PREFIX + endpoint.topic, endpoint.type, data, t, callerid=node.callerid)
            return
        self._recorder.write(endpoint.topic, endpoint.type, data, t, callerid=node.callerid, latching=endpoint.latch)
        if endpoint.topic in self.world.command_topics and endpoint.type == TWIST:
            linear, angular = decode_twist(data)
            self.world.command(endpoint.topic, linear=linear, angular=angular)
            self.received[endpoint.topic] = self.received.get(endpoint.topic, 0) + 1
        self._deliver(endpoint.topic, endpoint.type, data)

    def _output(self, node: _Node, line: OutputLine, t: int) -> None:
        topic = "/rosgrade/stdout" if line.stream == 1 else "/rosgrade/stderr"
        self._recorder.write(topic, "std_msgs/String", string_bytes(line.text), t, callerid=node.callerid)
        self._log_file.write(f"[{t / 1e9:12.6f}] {'out' if line.stream == 1 else 'err'} | {line.text}\n")

    # -- what the world does -----------------------------------------------------------------------------------
    def _next_seq(self, topic: str) -> int:
        seq = self.seq.get(topic, 0)
        self.seq[topic] = seq + 1
        return seq

    def _world_sample(self, sample: object) -> None:
        rec = self._recorder
        if isinstance(sample, OdometrySample):
            data = odometry_bytes(sample, self._next_seq(sample.topic))
            rec.write(sample.topic, "nav_msgs/Odometry", data, sample.t_ns, callerid=WORLD_CALLERID)
            self._deliver(sample.topic, "nav_msgs/Odometry", data)
        elif isinstance(sample, TransformSample):
            data = tf_bytes(sample, self._next_seq("/tf"))
            rec.write("/tf", "tf2_msgs/TFMessage", data, sample.t_ns, callerid=WORLD_CALLERID)
            self._deliver("/tf", "tf2_msgs/TFMessage", data)
        elif isinstance(sample, GroundTruthSample):
            data = ground_truth_bytes(sample, self._next_seq(GROUND_TRUTH_TOPIC),
                                      child_frame_id=self.world.mode.odometry.child_frame_id)
            rec.write(GROUND_TRUTH_TOPIC, "nav_msgs/Odometry", data, sample.t_ns, callerid=WORLD_CALLERID)
        elif isinstance(sample, CommandSample):
            rec.write(sample.topic, TWIST, twist_bytes(sample.linear, sample.angular), sample.t_ns,
                      callerid=DRIVER_CALLERID)

    def _deliver(self, topic: str, type_name: str, data: bytes) -> None:
        """Queue a message for every live subscriber of its topic and type, for the nodes' next batch."""
        for node in self.nodes:
            if not node.alive:
                continue
            for sub in node.link.state.subscribers.values():
                if sub.topic == topic and sub.type == type_name and not sub.closed:
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
            "odometry_topic": self.world.mode.odometry.topic,
            "command_topics": json.dumps(list(self.world.command_topics)),
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


def run(spec: RunSpec, recording: Path, log: Path) -> RunResult:
    """Run the scenario with its nodes, write the recording and the node log, and report what happened."""
    return Session(spec, recording, log).run()
