"""One wire flavour per run: how messages are spelled, encoded and recorded for ROS 1 (rospy) or ROS 2 (rclpy) nodes.

The session, the lockstep loop, limits and scoring are the same for both; what differs sits here: the type catalog
(definitions, md5sum or RIHS01 hash, strict decoding), the bytes of what the world publishes, the /rosout message,
the text channels' type, which velocity command types a robot base takes and how they decode.
"""
from __future__ import annotations

import dataclasses
import json
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import lru_cache

from grader.interfaces import InterfaceSet, catalog_for
from grader.recording import serialize as ros1
from grader.recording import serialize_cdr as cdr
from grader.recording.messages import MessageCatalog, default_catalog
from grader.recording.ros2_messages import Ros2Catalog, ros2_catalog
from sim.samples import (ColorSample, ContactSample, GroundTruthSample, ImuSample, JointStateSample, LogSample, OdometrySample,
                         ScanSample, TransformSample, TurtlePoseSample, Vec3)

TWIST = "geometry_msgs/Twist"
TWIST2 = "geometry_msgs/msg/Twist"
TWIST_STAMPED2 = "geometry_msgs/msg/TwistStamped"


# ROS 2: a node's DDS participant (made with its first node) discovers the world's and is discovered this long
# after: its endpoints made before match then, and /clock and the world's topics reach it from then on. Real rclpy
# (Fast DDS) is bimodal, 0.001-0.45 s or about 3 s (a missed announcement); this is the fast mode. DEVELOPERS.md.
DISCOVERY_NS = 100_000_000


class WireError(Exception):
    """A world produced a sample this flavour cannot encode, or a flavour name is unknown."""


@dataclass(frozen=True)
class Wire:
    """What one client library's runs put on the wire and in the recording."""

    name: str  # "ros1" | "ros2"
    client_library: str  # as students know it: "rospy" | "rclpy"
    discovery_ns: int  # how long after its start a node and the world know each other (0: at once)
    # rospy nodes read the run's parameter server; an rclpy node holds its own parameters, given its overrides only.
    shared_parameters: bool
    catalog: MessageCatalog | Ros2Catalog
    encoders: Mapping[type, Callable[[object, int], bytes]]
    log_type: str
    string_type: str
    twist_type: str  # what the grader's scripted driver records
    command_decoders: Mapping[str, Callable[[bytes], tuple[Vec3, Vec3]]]
    _log: Callable[[int, int, int, str, str, str, str, int, list[str]], bytes]  # as `log` takes them
    _string: Callable[[str], bytes]
    _twist: Callable[[Vec3, Vec3], bytes]

    def service_part(self, srv_type: str, part: str) -> str:
        """The message type of a service's "Request" or "Response"."""
        return self.catalog.service_part(srv_type, part)

    def start_params(self, tree: Mapping[str, object], sim_clock: bool, overrides: Mapping[str, object]) -> dict:
        """The parameters a node's START carries: the server's whole tree (rospy) or its own overrides (rclpy)."""
        if self.shared_parameters:
            return {"/" + name: value for name, value in tree.items()}
        return {"/use_sim_time": sim_clock, **overrides}

    def canonical(self, type_name: str) -> str:
        """A type name in this flavour's spelling (``pkg/Name`` or ``pkg/msg/Name``)."""
        return self.catalog.canonical(type_name)

    def encode(self, sample: object, seq: int) -> bytes:
        """The message bytes of one world sample, with header sequence number ``seq`` (ROS 1 only has one)."""
        try:
            encoder = self.encoders[type(sample)]
        except KeyError:
            raise WireError(f"no {self.name} encoding for a world sample of type {type(sample).__name__}") from None
        return encoder(sample, seq)

    def log(self, t_ns: int, seq: int, level: int, name: str, msg: str, file: str, function: str, line: int,
            topics: list[str]) -> bytes:
        """The /rosout message of a node's log call (``level`` in the node's own library's scale)."""
        return self._log(t_ns, seq, level, name, msg, file, function, line, topics)

    def string(self, text: str) -> bytes:
        return self._string(text)

    def twist(self, linear: Vec3, angular: Vec3) -> bytes:
        return self._twist(linear, angular)

    def decode_command(self, type_name: str, data: bytes) -> tuple[Vec3, Vec3]:
        """(linear, angular) of a velocity command of one of ``command_decoders``' types."""
        try:
            return self.command_decoders[type_name](data)
        except KeyError:
            raise WireError(f"{type_name} is not a velocity command type of {self.name}") from None

    def request_values(self, srv_type: str, data: bytes) -> dict[str, object]:
        """The fields of a ``srv_type`` request (bytes the node link has already checked) as plain values."""
        message = self.catalog.decode(self.service_part(srv_type, "Request"), data)
        return {f.name: getattr(message, f.name) for f in dataclasses.fields(message)
                if not f.name.startswith("__") and f.name != "structure_needs_at_least_one_member"}

    def response_bytes(self, srv_type: str, values: Mapping[str, object]) -> bytes:
        """The bytes of a ``srv_type`` response built from a world's plain values."""
        return self.part_bytes(srv_type, "Response", values)

    def part_bytes(self, srv_type: str, part: str, values: Mapping[str, object]) -> bytes:
        """The bytes of a ``srv_type`` "Request" or "Response" built from plain values."""
        type_name = self.service_part(srv_type, part)
        cls = self.catalog.message_class(type_name)
        if self.name == "ros2" and not values and "structure_needs_at_least_one_member" in cls.__dataclass_fields__:
            values = {"structure_needs_at_least_one_member": 0}
        return self.catalog.encode(type_name, cls(**values))


def _ros1_wire() -> Wire:
    return Wire(
        name="ros1", client_library="rospy", discovery_ns=0, shared_parameters=True, catalog=default_catalog(),
        encoders={OdometrySample: ros1.odometry_bytes, TransformSample: ros1.tf_bytes,
                  GroundTruthSample: ros1.ground_truth_bytes, ImuSample: ros1.imu_bytes,
                  JointStateSample: ros1.joint_state_bytes, ScanSample: ros1.laser_scan_bytes,
                  TurtlePoseSample: ros1.turtle_pose_bytes, ColorSample: ros1.color_bytes,
                  LogSample: ros1.world_log_bytes,
                  ContactSample: lambda sample, seq: ros1.string_bytes(contact_text(sample))},
        log_type="rosgraph_msgs/Log", string_type="std_msgs/String", twist_type=TWIST,
        command_decoders={TWIST: ros1.decode_twist},
        _log=ros1.log_bytes, _string=ros1.string_bytes, _twist=ros1.twist_bytes)


def _ros2_wire() -> Wire:
    return Wire(
        name="ros2", client_library="rclpy", discovery_ns=DISCOVERY_NS, shared_parameters=False,
        catalog=ros2_catalog(),
        encoders={OdometrySample: cdr.odometry_cdr, TransformSample: cdr.tf_cdr,
                  GroundTruthSample: cdr.ground_truth_cdr, ImuSample: cdr.imu_cdr,
                  JointStateSample: cdr.joint_state_cdr, ScanSample: cdr.laser_scan_cdr,
                  TurtlePoseSample: cdr.turtle_pose_cdr, ColorSample: cdr.color_cdr, LogSample: cdr.world_log_cdr,
                  ContactSample: lambda sample, seq: cdr.string_cdr(contact_text(sample))},
        log_type="rcl_interfaces/msg/Log", string_type="std_msgs/msg/String", twist_type=TWIST2,
        command_decoders={TWIST2: cdr.decode_twist_cdr, TWIST_STAMPED2: cdr.decode_twist_stamped_cdr},
        _log=_log_cdr, _string=cdr.string_cdr, _twist=cdr.twist_cdr)


def contact_text(sample: ContactSample) -> str:
    """A contact as the JSON text its std_msgs/String carries (no ROS message says what touched what where)."""
    x, y, z = sample.position
    return json.dumps({"obstacle": sample.obstacle, "x": x, "y": y, "z": z, "depth": sample.depth})


def _log_cdr(t_ns: int, seq: int, level: int, name: str, msg: str, file: str, function: str, line: int,
             topics: list[str]) -> bytes:
    """rcl_interfaces/msg/Log has neither a sequence number nor the node's topics."""
    return cdr.log_cdr(t_ns, level, name, msg, file, function, line)


def wire_for(flavour: str, interfaces: InterfaceSet | None = None) -> Wire:
    """The wire of a client library flavour ("ros1": rospy, "ros2": rclpy), with the submission's own types in its
    catalog when it has some."""
    base = _base_wire(flavour)
    if not interfaces:
        return base
    return dataclasses.replace(base, catalog=catalog_for(flavour, interfaces))


@lru_cache(maxsize=None)
def _base_wire(flavour: str) -> Wire:
    if flavour == "ros1":
        return _ros1_wire()
    if flavour == "ros2":
        return _ros2_wire()
    raise WireError(f"unknown client library flavour {flavour!r}: expected ros1 or ros2")

