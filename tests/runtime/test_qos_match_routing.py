"""The grader's routing connects two nodes' endpoints by the QoS they registered exactly as two real Jazzy rclpy
nodes connect (tests/conformance_ros2/qos_matrix_jazzy.json, recorded from a real publisher node and a real
subscriber node): every (offered, requested) pair of the record, resolved by rosgrade's rclpy as its publisher and
subscription send it in ADVERTISE/SUBSCRIBE, connects or not as recorded, whichever node started first
(``sub_first``), and both sides' warnings name the policy the record names. Bad QoS in a frame is a clear violation."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from grader.nodelib.common import rosgrade_qos
from grader.runtime.node_link import Endpoint, ProtocolViolation, _qos
from grader.runtime.qos_match import connects, mismatch
from tests.nodelib_ros2_rclpy import ros2_grader  # noqa: F401 - puts the ROS 2 import roots on sys.path

from rclpy.qos import (DurabilityPolicy, QoSProfile, ReliabilityPolicy, offered_policies,  # noqa: E402
                       requested_policies, wire_policies)

RECORD = json.loads((Path(__file__).resolve().parents[1] / "conformance_ros2" / "qos_matrix_jazzy.json").read_text())
_SHORT = {p[:2] + p[-2:]: p for p in ("reliable", "best_effort", "best_available", "system_default", "volatile",
                                      "transient_local")}


def _profile(reliability: str, durability: str) -> QoSProfile:
    return QoSProfile(depth=10, reliability=ReliabilityPolicy[reliability.upper()],
                      durability=DurabilityPolicy[durability.upper()])


def _endpoint(qos: tuple[str, str] | None) -> Endpoint:
    return Endpoint(ident=1, topic="/chatter", type="std_msgs/msg/String", md5sum="*", queue_size=10, latch=False,
                    registered_ns=0, qos=qos)


@pytest.mark.parametrize("role", ["sub", "sub_discovered", "sub_first"])
def test_routing_connects_as_real_rclpy_nodes(role: str) -> None:
    """Which pairs connect, and the policy each side's warning names (publisher's and subscription's texts)."""
    routed, names = {}, {}
    for name in RECORD[role]["received"]:
        r1, d1, r2, d2 = (_SHORT[key] for key in name.removeprefix("/qos_").split("_"))
        offers = offered_policies(_profile(r1, d1))
        discovered = [offers] if role == "sub_discovered" else []
        pub = _endpoint(wire_policies(offers))
        sub = _endpoint(wire_policies(requested_policies(_profile(r2, d2), discovered)))
        routed[name] = connects(pub, sub)
        if not routed[name]:
            names[name] = mismatch(pub, sub)
    assert routed == RECORD[role]["received"]
    for side, text in (("subscription_warnings", rosgrade_qos.SUBSCRIPTION_WARNING),
                       ("publisher_warnings", rosgrade_qos.PUBLISHER_WARNING)):
        assert sorted(text.format(topic=name, policy=policy) for name, policy in names.items()) == RECORD[role][side]


def test_endpoints_without_qos_match_everything() -> None:
    """ROS 1 endpoints register no QoS: the routing connects them as before."""
    assert connects(_endpoint(None), _endpoint(("RELIABLE", "TRANSIENT_LOCAL")))
    assert connects(_endpoint(("BEST_EFFORT", "VOLATILE")), _endpoint(None))
    assert not connects(_endpoint(("BEST_EFFORT", "VOLATILE")), _endpoint(("RELIABLE", "VOLATILE")))


@pytest.mark.parametrize("value, says", [(["RELIABLE"], "qos lists 1 policies"),
                                         (["SYSTEM_DEFAULT", "VOLATILE"], "is not a reliability in"),
                                         (["RELIABLE", "KEEP_LAST"], "a durability in")])
def test_bad_qos_in_a_frame_is_a_clear_violation(value: list[str], says: str) -> None:
    with pytest.raises(ProtocolViolation, match=says):
        _qos(value)


def test_bad_qos_events_and_world_qos_are_clear_errors() -> None:
    """A node refuses a BATCH or START whose QoS parts are not what the grader sends, saying what was expected."""
    import rosgrade_channel as ch
    from rosgrade_node.bootstrap import BootstrapError, _world_qos
    from rosgrade_node.link import _qos_events
    assert _qos_events([[3, "RELIABILITY"]]) == [(3, "RELIABILITY")]
    with pytest.raises(ch.ChannelError, match="BATCH qos must list"):
        _qos_events([[3, "DEPTH"]])
    assert _world_qos({"/scan": ["BEST_EFFORT", "VOLATILE"]}) == {"/scan": ("BEST_EFFORT", "VOLATILE")}
    with pytest.raises(BootstrapError, match="START world_qos must map topics"):
        _world_qos({"/scan": ["SENSOR_DATA", "VOLATILE"]})
