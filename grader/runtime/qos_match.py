"""Whether a node's publisher and a node's subscriber connect, by the QoS each registered (ROS 2), and why not.

The routing (Session.receivers) asks ``connects`` for every pair on a topic; the rule is the one the node library
uses (rosgrade_qos), measured against two real Jazzy rclpy nodes. An endpoint without QoS (ROS 1) matches all.
"""
from __future__ import annotations

from grader.nodelib.common import rosgrade_qos
from grader.runtime.node_link import Endpoint


def mismatch(publisher: Endpoint, subscriber: Endpoint) -> str | None:
    """The last policy ("RELIABILITY" or "DURABILITY") in which the publisher offers less than the subscriber
    requests, or None when they connect."""
    if publisher.qos is None or subscriber.qos is None:
        return None
    return rosgrade_qos.incompatible(publisher.qos, subscriber.qos)


def connects(publisher: Endpoint, subscriber: Endpoint) -> bool:
    return mismatch(publisher, subscriber) is None
