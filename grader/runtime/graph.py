"""The run's ROS graph as one node sees it at its sim time: the other nodes, the world's node and /rosgrade.

A node asks with a GRAPH frame and gets a GRAPH_VIEW at once (rosgrade_channel): its own endpoints it knows itself,
so the view lists the others. Nodes run one at a time in lockstep, so the answer at the asker's time is the same on
every run. Under ROS 2 a node sees another only after DDS discovery (``discovery_ns`` after both started, the
world's from its own start); under ROS 1 the master knows every registration at once. The encoded view is kept until
a node's endpoints or discovery change, so a node asking in a loop costs the grader a comparison and a send per ask,
and a view is bounded by the frame cap.
"""
from __future__ import annotations

import json
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from grader.nodelib.common import rosgrade_channel as ch
from grader.runtime.node_link import NodeState

PARTICIPANT = "/rosgrade"


class GraphError(Exception):
    """A graph view asked for a node the run does not have."""


@dataclass(frozen=True)
class Peer:
    """A node of the run as the graph holds it: its channel state and whether its process still runs."""

    state: NodeState
    alive: bool


@dataclass(frozen=True)
class FixedNode:
    """A node the grader stands for (the world's, /rosgrade): its name and endpoints, visible from the start."""

    name: str
    kind: str  # "world" (the world's node) or "grader" (/rosgrade)
    pub: tuple[tuple[str, str], ...] = ()
    sub: tuple[tuple[str, str], ...] = ()
    srv: tuple[tuple[str, str], ...] = ()

    def entry(self) -> dict:
        return {"name": self.name, "kind": self.kind, "pub": [list(p) for p in sorted(set(self.pub))],
                "sub": [list(s) for s in sorted(set(self.sub))], "srv": [list(s) for s in sorted(set(self.srv))]}


class GraphView:
    """Answers GRAPH for the run's nodes; ``peers`` and ``fixed`` are read at each answer (they change as it runs)."""

    def __init__(self, discovery_ns: int, peers: Callable[[], list[Peer]], fixed: Callable[[], Iterable[FixedNode]],
                 limit: int = ch.MAX_FRAME_BYTES - 64) -> None:
        self._discovery_ns = discovery_ns
        self._peers = peers
        self._fixed = fixed
        self._limit = limit
        self._cached: tuple[tuple, bytes] | None = None

    def answer(self, asker: int, t_ns: int) -> bytes:
        """The GRAPH_VIEW payload for node ``asker`` (an index of ``peers``) at ``t_ns``."""
        peers = self._peers()
        if not 0 <= asker < len(peers):
            raise GraphError(f"no node {asker} in a run of {len(peers)}")
        fixed = tuple(self._fixed())
        seen = [self._discovered(peer, t_ns) for peer in peers]
        # What the view depends on, in O(nodes): a node asking again and again costs one comparison per ask.
        key = (asker, fixed, tuple((p.state.graph_version, p.alive, s) for p, s in zip(peers, seen)))
        if self._cached is not None and self._cached[0] == key:
            return self._cached[1]
        nodes = [] if not seen[asker] else [node.entry() for node in fixed] + [
            _entry(peer.state) for index, peer in enumerate(peers) if index != asker and peer.alive and seen[index]]
        payload = json.dumps({"nodes": nodes}, separators=(",", ":")).encode()
        while len(payload) > self._limit and nodes:  # only a run of flooding nodes gets here: the last ones go
            nodes.pop()
            payload = json.dumps({"nodes": nodes, "cut": True}, separators=(",", ":")).encode()
        self._cached = (key, payload)
        return payload

    def _discovered(self, peer: Peer, t_ns: int) -> bool:
        """Whether a node has a name on the graph and its DDS discovery (none under ROS 1) is over at ``t_ns``."""
        st = peer.state
        return st.name is not None and st.init_ns is not None and t_ns >= st.init_ns + self._discovery_ns


def _entry(st: NodeState) -> dict:
    """A node of the run as GRAPH_VIEW lists it. Nodes run one at a time in lockstep, so everything another node
    registered happened at or before the asker's time."""
    return {"name": st.name, "kind": "node", "pub": _open(st.publishers.values()),
            "sub": _open(st.subscribers.values()), "srv": _open(st.services.values())}


def _open(endpoints) -> list[list[str]]:
    """[topic, type] of the open endpoints, sorted, each pair once."""
    return [list(pair) for pair in sorted({(e.topic, e.type) for e in endpoints if not e.closed})]


def for_session(session, plan) -> GraphView:
    """The view of a running session (grader/runtime/session.py): its nodes, its world's node and, when the
    scenario acts (``plan``: scenario_participant.ParticipantPlan), /rosgrade."""
    acts = plan.calls or plan.goals or plan.publications
    participant = FixedNode(PARTICIPANT, "grader", pub=tuple((p.topic, p.type) for p in plan.publications))

    def fixed() -> Iterable[FixedNode]:
        yield from _world_nodes(session)
        if acts:
            yield participant

    return GraphView(session.discovery_ns, lambda: [Peer(n.link.state, n.alive) for n in session.nodes], fixed)


def _world_nodes(session) -> Iterable[FixedNode]:
    """The world's node, or each of its nodes when it stands for several (turtlesim's further windows: a topic, a
    command topic or a service under a window's namespace is that window node's)."""
    world = session.world
    others = sorted({p.node for p in session.publications.values() if p.node}, key=len, reverse=True)

    def owner(name: str) -> str:
        return next((node for node in others if name.startswith(node.rpartition("/")[0] + "/")), world.node_name)

    subs = [(topic, type_name) for topic in world.command_topics for type_name in sorted(session.command_types)]
    for node in (world.node_name, *others):
        yield FixedNode(node, "world", pub=tuple(t for t in session.world_topics if owner(t[0]) == node),
                        sub=tuple(t for t in subs if owner(t[0]) == node),
                        srv=tuple((s.name, s.type) for s in world.services if owner(s.name) == node))
