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
from grader.runtime.node_link import Endpoint

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


def robot_hears(publisher: Endpoint, world) -> bool:
    return robot_mismatch(publisher, world) is None


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
        policy = robot_mismatch(pub, session.world) if pub.topic in session.world.command_topics else None
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
