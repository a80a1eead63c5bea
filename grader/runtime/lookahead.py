"""Running the world ahead of a node: one BATCH carries the later moments the lockstep would stop at for it, so a
node that only waits for messages or repeats its command costs no round trip per message. The world is run ahead,
recorded as far as the node says it got (MOMENT), and taken back to that moment if it stopped earlier: the
recording is bit for bit what the plain lockstep gives."""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from grader import timing
from grader.runtime.node_link import ROBOT, ProtocolViolation

if TYPE_CHECKING:
    from grader.runtime.session import Session, _Encoded, _Node

# The most later moments one BATCH carries (0: none, the plain lockstep). A node that stops early gets fewer next
# time: the world run ahead past the moment it stopped at is taken back, and so wasted.
MAX_MOMENTS = 64
# How far past its wake-up the world runs ahead of a node, at most and at first: the node runs on its own there
# while it only repeats its command (or logs, prints); a node that acts there costs the world run past that point.
MAX_FREE_NS = 250_000_000
FIRST_FREE_NS = 50_000_000
# How far the world runs ahead of a node that waits only for messages.
MAX_AHEAD_NS = 2_000_000_000
# Sim time between two snapshots of a world run ahead: a snapshot costs about what 2 ms of physics do, and taking the
# world back re-runs the physics from the last one before the moment the node stopped at.
SNAPSHOT_SPACING_NS = 100_000_000


@dataclass
class Pace:
    """How far the world runs ahead of one node: later moments its next BATCH may carry (doubled while it runs them
    all), and, after batches whose first moment it already acted at, delivery steps taken one by one before trying
    again."""

    moments_cap: int = 1
    misses: int = 0
    pause: int = 0
    # How far past its wake-up the world runs ahead (0: to the wake-up only, until the node wakes and only
    # repeats what it did, since it acted at its wake-up itself last time).
    free_ns: int = FIRST_FREE_NS


@dataclass
class Speculation:
    """A world run ahead of a node from the batch's time ``t_ns`` to ``until_ns``, recorded as the node says how far
    it got (MOMENT), and taken back to where it stopped if that was earlier."""

    node: _Node
    t_ns: int
    wake_ns: int | None  # the node's wake-up when the batch went out
    inert: dict[int, bool]  # the batch's inert publishers (see rosgrade_channel.encode_batch)
    # The world before some of the advances, by time (see SNAPSHOT_SPACING_NS).
    snapshots: list[tuple[int, object]] = field(default_factory=list)
    items: list[_Encoded] = field(default_factory=list)  # what the world published on the way, in time order
    later: list[tuple[int, int, list[tuple[int, bytes]]]] = field(default_factory=list)  # (t, clock, deliveries)
    until_ns: int = 0
    now_ns: int = 0  # the moment the node is at
    told: bool = False  # the node has named a moment
    committed: int = 0  # items recorded so far
    renewed_ns: int | None = None  # when the node last repeated the robot's command
    acted: bool = False  # the node did something that ended its run on its own (see on_act)
    settled: bool = False

class Lookahead:
    """The session's running ahead: started for a node's BATCH, told its MOMENTs, settled when it stops."""

    def __init__(self, session: Session) -> None:
        self.session = session

    def start(self, node: _Node, t: int) -> Speculation | None:
        """Run the world ahead of a node at t for one BATCH of moments; None when the lockstep must go step by step
        (several nodes, a shutdown, a world without rollback, a node that acted at once lately).

        The later moments are the times the lockstep would stop at to deliver to the node, up to a horizon: a while
        past its wake-up (``free_ns``, which the node's record sets), before anything else that would change its
        batches (a publisher connecting, the shutdown, the end) and, if the node may repeat the robot's command,
        before that command would time out or a scripted one replace it. What the world publishes on the way is
        encoded but not yet recorded."""
        snapshot = getattr(self.session.world, "snapshot", None)
        session = self.session
        if not MAX_MOMENTS or snapshot is None or node.term_ns is not None or sum(n.alive for n in session.nodes) != 1 \
                or node.link.state.init_ns is None or t < node.link.state.init_ns + session.discovery_ns:
            return None  # (before rclpy's discovery: the node would take its own wake-ups' /clock ticks as given)
        if node.pace.pause:
            node.pace.pause -= 1
            return None
        wake = None if node.wake_ns is None else max(node.wake_ns, t)  # t: it wakes now, by its own deadline
        holds = self.session.world.command_holds_until_ns()
        inert = self._inert(node, t, holds)
        bounds = [self.session.end_ns, *self.session.latched_connect_times(t)]
        if (call_ns := self.session.caller.next_ns()) is not None:  # the scenario's next service call
            bounds.append(max(call_ns, t + 1))
        if (start_ns := session.starts.next_ns()) is not None:  # a node launch starts later
            bounds.append(max(start_ns, t + 1))
        if self.session.shutdown_ns is not None and not self.session.shutdown_sent:
            bounds.append(self.session.shutdown_ns)
        bounds += [ready for pub in node.link.state.publishers.values()
                   if not pub.closed and (ready := self.session.ready_ns(pub)) > t]
        if False in inert.values():  # a repeated command must find the base as it left it
            scripted = self.session.world.next_scripted_command_ns
            bounds += [b for b in (None if holds is None else holds + 1, scripted) if b is not None]
        limit = min(min(bounds) - 1, t + MAX_AHEAD_NS if wake is None else wake + node.pace.free_ns)
        due = self.session.world.next_output_ns(self.session.listened)
        if (wake is None or wake > limit) and (due is None or due > limit):
            return None  # nothing for the node before the horizon: running ahead could only be taken back
        ahead = Speculation(node, t, wake, inert, now_ns=t)
        started = time.perf_counter()
        while len(ahead.later) < node.pace.moments_cap:
            target = due if due is not None and due <= limit else limit
            if target <= self.session.world.time_ns:
                break
            if not ahead.snapshots or self.session.world.time_ns - ahead.snapshots[-1][0] >= SNAPSHOT_SPACING_NS:
                ahead.snapshots.append((self.session.world.time_ns, snapshot()))
            samples = self.session.world.advance_to(target)
            stepped = time.perf_counter()
            timing.add("physics and sensors", stepped - started)
            encoded = [self.session.encode(sample) for sample in samples]
            ahead.items += encoded
            deliveries = [(sub.ident, item.data) for item in encoded
                          if item.to_nodes and self.session.discovered(node, item.t_ns)
                          for sub in node.listening(item.topic, item.type)]
            if deliveries:
                ahead.later.append((target, self.session.clock_ns(node.link, target), deliveries))
            due = self.session.world.next_output_ns(self.session.listened)
            started = time.perf_counter()
            timing.add("world messages (encode, record, queue)", started - stepped)
        ahead.until_ns = self.session.world.time_ns
        if ahead.until_ns == t or (not ahead.later and (wake is None or wake > ahead.until_ns)):
            self._take_back(ahead, t)  # nothing the node would do on its own
            return None
        return ahead

    def _inert(self, node: _Node, t: int, holds: int | None) -> dict[int, bool]:
        """The node's publishers whose messages cannot change the world or its batches while nothing else changes:
        True for any message (recorded only), False when only its last message again is (the robot's command in
        force, repeated, while it holds: until ``holds``, the base's command timeout). Latched publishers never are: a
        latched message is kept for later subscribers."""
        inert: dict[int, bool] = {}
        for pub in node.link.state.publishers.values():
            if pub.closed or pub.latch:
                continue
            if self.session.ignored(pub) or t < self.session.ready_ns(pub):
                inert[pub.ident] = True  # ignored, or lost before its publisher connects
                continue
            receivers = self.session.receivers(pub, t)
            if not receivers:
                inert[pub.ident] = True
            elif receivers == [ROBOT] and pub.last_data is not None \
                    and self.session.robot_command == (pub.type, pub.last_data) and (holds is None or holds > t):
                inert[pub.ident] = False
        return inert

    def moment(self, ahead: Speculation, t_ns: int) -> int:
        """The node says it is at ``t_ns`` (MOMENT): record what the world did up to then; returns the time."""
        if not ahead.t_ns <= t_ns <= ahead.until_ns:
            raise ProtocolViolation(f"MOMENT at {t_ns} ns, outside its batch ({ahead.t_ns}..{ahead.until_ns} ns)")
        if t_ns < ahead.now_ns or (ahead.told and t_ns == ahead.now_ns):
            raise ProtocolViolation(f"MOMENT at {t_ns} ns, not after the moment before it ({ahead.now_ns} ns)")
        ahead.now_ns, ahead.told = t_ns, True
        self._commit(ahead, t_ns)
        return t_ns

    def _commit(self, ahead: Speculation, t_ns: int) -> None:
        """Record the world's messages run ahead up to ``t_ns`` (already delivered, if they were for the node)."""
        items, n = ahead.items, ahead.committed
        while n < len(items) and items[n].t_ns <= t_ns:
            self.session.commit(items[n], queue=False)
            n += 1
        ahead.committed = n

    def settle(self, ahead: Speculation, exact: bool) -> None:
        """The node stopped at ``ahead.now_ns``: acted there (or ended), or sent WAIT. Record the world up to that
        moment and take it back there; after a WAIT with every later moment run and a wake-up past the horizon the
        world may stay where it ran ahead to, since the lockstep would have gone there with nothing to stop for."""
        node, t = ahead.node, ahead.now_ns
        ahead.acted = ahead.acted or exact
        self._commit(ahead, t)
        passed = sum(1 for when, _, _ in ahead.later if when <= t)
        if not exact and passed == len(ahead.later) and (node.wake_ns is None or node.wake_ns > ahead.until_ns):
            self._commit(ahead, ahead.until_ns)
        else:
            self._take_back(ahead, t)
        if ahead.renewed_ns is not None:
            self.session.world.repeat_command(ahead.renewed_ns)
        ahead.settled = True
        self.session.ahead = None
        timing.count("moments run without a round trip", passed)
        wake, pace = ahead.wake_ns, node.pace
        if ahead.acted and t == ahead.t_ns:  # it acted at once: the lockstep is cheaper for a while, then try again
            pace.misses += 1
            pace.moments_cap, pace.pause = 1, min(2 ** pace.misses, MAX_MOMENTS)
            pace.free_ns = FIRST_FREE_NS
            return
        pace.misses = 0
        pace.moments_cap = min(pace.moments_cap * 2, MAX_MOMENTS) if passed == len(ahead.later) else max(1, passed)
        if wake is None:
            return
        if not ahead.acted:  # past its wake-up (or only up to it) it did nothing that mattered: run further
            pace.free_ns = min(max(2 * pace.free_ns, FIRST_FREE_NS), MAX_FREE_NS)
        else:  # a P controller's changing commands, say: run ahead no further than it got this time
            pace.free_ns = max(0, t - wake)

    def _take_back(self, ahead: Speculation, t_ns: int) -> None:
        """Put the world back where it was at ``t_ns`` (MuJoCo's state and the world's own, then the same advance
        again: bit for bit what the lockstep would have) and forget what it published after then."""
        if self.session.world.time_ns == t_ns:
            return
        started = time.perf_counter()
        at, snapshot = next((at, snapshot) for at, snapshot in reversed(ahead.snapshots) if at <= t_ns)
        timing.count("simulated milliseconds run ahead in vain", (self.session.world.time_ns - at) / 1e6)
        self.session.world.restore(snapshot)
        if t_ns > at:
            self.session.world.advance_to(t_ns)
        dropped = ahead.items[ahead.committed:]
        del ahead.items[ahead.committed:]
        for item in dropped:
            if item.seq >= 0:
                self.session.seq[item.topic] = min(self.session.seq[item.topic], item.seq)
        timing.add("world run ahead and taken back", time.perf_counter() - started)
        timing.count("world advances taken back")
