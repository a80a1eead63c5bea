"""Whether a ROS 2 publisher reaches a subscriber by the QoS each declared, and the findings that name a mismatch.

The world's own topics are matched by the node library (it logs rclpy's warning); ``world_mismatch`` says what it
decided, for the report.

The routing (Session.receivers) asks ``connects`` for every pair of nodes' endpoints on a topic and ``robot_hears``
for a node's command publisher; the rule is the one the node library uses (rosgrade_qos), measured against two real
Jazzy rclpy nodes. An endpoint without QoS (ROS 1) matches all.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from grader.nodelib.common import rosgrade_qos
from grader.runtime.node_link import ROBOT, Endpoint

if TYPE_CHECKING:
    from grader.runtime.session import Session, _Node

_POLICY_INDEX = {"RELIABILITY": 0, "DURABILITY": 1}


def mismatch(publisher: Endpoint, subscriber: Endpoint) -> str | None:
    """The last policy ("RELIABILITY" or "DURABILITY") in which the publisher offers less than the subscriber
    requests, or None when they connect."""
    if publisher.qos is None or subscriber.qos is None:
        return None
    return rosgrade_qos.incompatible(publisher.qos, subscriber.qos)


def connects(publisher: Endpoint, subscriber: Endpoint) -> bool:
    return mismatch(publisher, subscriber) is None


def robot_mismatch(publisher: Endpoint, world) -> str | None:
    """The policy in which a node's command publisher fails the robot's command subscriber (the world's
    ``command_qos``), or None."""
    return None if publisher.qos is None else rosgrade_qos.incompatible(publisher.qos, world.command_qos)


def robot_hears(publisher: Endpoint, session: Session) -> bool:
    """Whether the robot's base takes what a node's publisher sends: a command topic, a command type, matching QoS."""
    return _commands(publisher, session) and robot_mismatch(publisher, session.world) is None


def _commands(publisher: Endpoint, session: Session) -> bool:
    """Whether the publisher is on one of the robot's command topics with a command type."""
    return publisher.topic in session.world.command_topics and publisher.type in session.command_types


def news(session: Session, node: _Node, t: int) -> list[tuple[int, str]]:
    """(handle, policy) for each of the node's endpoints per peer endpoint discovered by t whose QoS it cannot
    match, told once: what rclpy's default event handlers log, on the subscription's and the publisher's side."""
    events: list[tuple[int, str]] = []
    for index, other in enumerate(session.nodes):
        if not other.alive:
            continue
        for sub in node.link.state.subscribers.values():
            if session.discovered(node, t) and not sub.closed:
                events += _tell(sub, index, [pub for pub in other.link.state.publishers.values() if not pub.closed
                                             and t >= max(session.ready_ns(pub), sub.registered_ns)], mismatch)
        for pub in node.link.state.publishers.values():
            if session.discovered(other, t) and not pub.closed and t >= session.ready_ns(pub):
                events += _tell(pub, index, [sub for sub in other.link.state.subscribers.values() if not sub.closed
                                             and t >= sub.registered_ns], lambda sub, pub: mismatch(pub, sub))
    for pub in node.link.state.publishers.values():  # the robot's command subscriber, once the publisher connects
        if (ROBOT not in pub.qos_told and not pub.closed and t >= session.ready_ns(pub) and _commands(pub, session)
                and (policy := robot_mismatch(pub, session.world)) is not None):
            pub.qos_told.add(ROBOT)
            events.append((pub.ident, policy))
    return events


def _tell(mine: Endpoint, index: int, peers: list[Endpoint], rule) -> list[tuple[int, str]]:
    """Events for ``mine`` about the peers on its topic (of node ``index``) it has not been told about yet;
    ``rule(peer, mine)`` is the policy they fail in, or None."""
    events = []
    for peer in peers:
        if (peer.topic, peer.type) == (mine.topic, mine.type) and (index, peer.ident) not in mine.qos_told:
            policy = rule(peer, mine)
            if policy is not None:
                mine.qos_told.add((index, peer.ident))
                events.append((mine.ident, policy))
    return events


def world_mismatch(session: Session, subscriber: Endpoint) -> str | None:
    """The policy in which the world's publisher of the subscriber's topic fails it (the node's client library then
    drops every message the grader hands it), or None."""
    publication = session.publications.get(subscriber.topic)
    if publication is None or not publication.to_nodes or subscriber.qos is None:
        return None
    return rosgrade_qos.incompatible(publication.qos, subscriber.qos)


def heard(session: Session, subscriber: Endpoint) -> int:
    """How many messages reached the subscriber's callback side: none when QoS kept the world's from it."""
    return 0 if world_mismatch(session, subscriber) is not None else subscriber.count


def findings(session: Session, node: _Node, here: str) -> list[str]:
    """What a student reads about the node's endpoints that QoS kept apart: its command publisher and the robot
    (``here``: the robot as users know it), its subscriptions and other nodes' publishers."""
    label, notes = node.outcome.script, []
    for pub in node.link.state.publishers.values():
        policy = robot_mismatch(pub, session.world) if _commands(pub, session) else None
        if policy is not None:
            i = _POLICY_INDEX[policy]
            notes.append(f"{label}'s publisher on {pub.topic} offers {pub.qos[i]} QoS, but {here}'s subscriber "
                         f"there requests {session.world.command_qos[i]} (incompatible {policy}): {here} never "
                         f"received a command, as on ROS 2. Use the default QoS: "
                         f"create_publisher(..., '{pub.topic.lstrip('/')}', 10).")
    for sub in node.link.state.subscribers.values():
        policy = world_mismatch(session, sub)
        if policy is not None:
            i = _POLICY_INDEX[policy]
            notes.append(f"{label}'s subscription to {sub.topic} requests {sub.qos[i]} QoS, but {here}'s publisher "
                         f"offers {session.publications[sub.topic].qos[i]} (incompatible {policy}): no message "
                         "arrived, as on ROS 2. Subscribe with qos_profile_sensor_data (from rclpy.qos), which "
                         "hears it.")
        for other in session.nodes:
            for pub in other.link.state.publishers.values():
                policy = mismatch(pub, sub) if (pub.topic, pub.type) == (sub.topic, sub.type) else None
                if policy is not None:
                    i = _POLICY_INDEX[policy]
                    notes.append(f"{label}'s subscription to {sub.topic} requests {sub.qos[i]} QoS, but "
                                 f"{other.outcome.script}'s publisher offers {pub.qos[i]} (incompatible {policy}): "
                                 "no messages went from one to the other, as on ROS 2. Give both the same QoS "
                                 "(the default: a depth of 10).")
    return notes
