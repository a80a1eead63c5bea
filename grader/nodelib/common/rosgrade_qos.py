"""The ROS 2 QoS compatibility rule (stdlib only): the node library and the grader's routing decide with this one.

Policies are named as rclpy names its enum members ("RELIABLE", "BEST_EFFORT", "VOLATILE", "TRANSIENT_LOCAL"), after
SYSTEM_DEFAULT and BEST_AVAILABLE have been resolved. Measured against two real Jazzy rclpy nodes (rmw_fastrtps):
tests/conformance_ros2/qos_matrix_jazzy.json.
"""
from __future__ import annotations

RELIABILITIES = frozenset({"RELIABLE", "BEST_EFFORT"})
DURABILITIES = frozenset({"VOLATILE", "TRANSIENT_LOCAL"})

# What the subscription's side logs (rclpy's default incompatible-QoS event handler), and the publisher's side.
SUBSCRIPTION_WARNING = ("New publisher discovered on topic '{topic}', offering incompatible QoS. "
                        "No messages will be received from it. Last incompatible policy: {policy}")
PUBLISHER_WARNING = ("New subscription discovered on topic '{topic}', requesting incompatible QoS. "
                     "No messages will be sent to it. Last incompatible policy: {policy}")


class QoSRuleError(ValueError):
    """A policy name that is not a resolved reliability or durability."""


def check(reliability: str, durability: str) -> tuple[str, str]:
    """(reliability, durability) when both are resolved policy names, else QoSRuleError saying which is not."""
    if reliability not in RELIABILITIES or durability not in DURABILITIES:
        raise QoSRuleError(f"QoS ({reliability!r}, {durability!r}) is not a reliability in {sorted(RELIABILITIES)} "
                           f"and a durability in {sorted(DURABILITIES)}")
    return reliability, durability


def incompatible(offered: tuple[str, str], requested: tuple[str, str]) -> str | None:
    """The last policy ("DURABILITY" or "RELIABILITY") in which a publisher offers less than a subscription requests,
    or None when they match.

    RELIABLE requested gets nothing from BEST_EFFORT offered, TRANSIENT_LOCAL requested nothing from VOLATILE offered;
    the reverse pairs match. Reliability is checked after durability, so it is the one named when both differ.
    """
    last = None
    if offered[1] == "VOLATILE" and requested[1] == "TRANSIENT_LOCAL":
        last = "DURABILITY"
    if offered[0] == "BEST_EFFORT" and requested[0] == "RELIABLE":
        last = "RELIABILITY"
    return last
