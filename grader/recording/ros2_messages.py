"""ROS 2 message types rosgrade knows: ``ros2msg`` schema text, Jazzy type hashes and strict CDR decoding.

The ROS 2 counterpart of messages.py, built on rosbags' Jazzy type store (plus std_srvs and turtlesim, which it
lacks), so definitions and RIHS01 hashes are those of a Jazzy install. Types are spelled ``pkg/msg/Name``, as rclpy
and rosbag2 spell them; ``pkg/Name`` is accepted too.
"""
from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from functools import lru_cache

from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from rosbags.typesys.base import Nodetype
from rosbags.typesys.store import Typestore

from grader.nodelib.ros2.rosgrade_rosidl._defs import SERVICES as NODE_SERVICE_HASHES
from grader.recording.errors import RecordingError

_TYPE_NAME = re.compile(r"^([A-Za-z][A-Za-z0-9_]*)/(?:(msg|srv|action)/)?([A-Za-z][A-Za-z0-9_]*)$")

# turtlesim's messages (rosbags' Jazzy store lacks them), as in their Jazzy .msg files.
TURTLESIM_MESSAGES = {
    "turtlesim/msg/Pose": "float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\nfloat32 angular_velocity\n",
    "turtlesim/msg/Color": "uint8 r\nuint8 g\nuint8 b\n",
}

# The services every rclpy node serves for its parameters (rcl_interfaces/srv, Jazzy), as (request, response).
RCL_INTERFACES_SERVICES = {
    "rcl_interfaces/srv/DescribeParameters": ("string[] names", "rcl_interfaces/ParameterDescriptor[] descriptors"),
    "rcl_interfaces/srv/GetParameterTypes": ("string[] names", "uint8[] types"),
    "rcl_interfaces/srv/GetParameters": ("string[] names", "rcl_interfaces/ParameterValue[] values"),
    "rcl_interfaces/srv/ListParameters": ("uint64 DEPTH_RECURSIVE=0\nstring[] prefixes\nuint64 depth",
                                          "rcl_interfaces/ListParametersResult result"),
    "rcl_interfaces/srv/SetParameters": ("rcl_interfaces/Parameter[] parameters",
                                         "rcl_interfaces/SetParametersResult[] results"),
    "rcl_interfaces/srv/SetParametersAtomically": ("rcl_interfaces/Parameter[] parameters",
                                                   "rcl_interfaces/SetParametersResult result"),
}

# The service by which every ROS 2 action's client cancels goals (action_msgs/srv/CancelGoal.srv, Jazzy).
CANCEL_GOAL = {"action_msgs/srv/CancelGoal": (
    "action_msgs/GoalInfo goal_info",
    "int8 ERROR_NONE=0\nint8 ERROR_REJECTED=1\nint8 ERROR_UNKNOWN_GOAL_ID=2\nint8 ERROR_GOAL_TERMINATED=3\n"
    "int8 return_code\naction_msgs/GoalInfo[] goals_canceling")}

# Built-in actions as (goal, result, feedback) definitions: example_interfaces' Fibonacci (the action tutorial's) and
# turtlesim's RotateAbsolute (each turtle's rotate_absolute, the CLI tutorials' action).
ACTIONS = {"example_interfaces/action/Fibonacci": ("int32 order", "int32[] sequence", "int32[] sequence"),
           "turtlesim/action/RotateAbsolute": ("float32 theta", "float32 delta", "float32 remaining")}

# Services as (request, response) definitions.
SERVICES = {
    **RCL_INTERFACES_SERVICES,
    **CANCEL_GOAL,
    "std_srvs/srv/Empty": ("", ""),
    "std_srvs/srv/Trigger": ("", "bool success\nstring message"),
    "std_srvs/srv/SetBool": ("bool data", "bool success\nstring message"),
    "example_interfaces/srv/AddTwoInts": ("int64 a\nint64 b", "int64 sum"),
    "turtlesim/srv/Kill": ("string name", ""),
    "turtlesim/srv/SetPen": ("uint8 r\nuint8 g\nuint8 b\nuint8 width\nuint8 off", ""),
    "turtlesim/srv/Spawn": ("float32 x\nfloat32 y\nfloat32 theta\nstring name", "string name"),
    "turtlesim/srv/TeleportAbsolute": ("float32 x\nfloat32 y\nfloat32 theta", ""),
    "turtlesim/srv/TeleportRelative": ("float32 linear\nfloat32 angular", ""),
}


# ROS 1 types whose role ROS 2 gives another package's type (rosgraph_msgs has only Clock in ROS 2).
_ROS2_COUNTERPARTS = {"rosgraph_msgs/Log": "rcl_interfaces/msg/Log"}

# rosidl gives a structure with no fields this one uint8 member, on the wire too.
_EMPTY_STRUCT = "uint8 structure_needs_at_least_one_member"


def ros2_type_name(type_name: str) -> str:
    """``pkg/msg/Name`` for ``pkg/Name`` or ``pkg/msg/Name`` (``pkg/srv/Name`` stays); RecordingError otherwise."""
    match = _TYPE_NAME.match(type_name)
    if match is None:
        raise RecordingError(f"{type_name!r} is not a ROS 2 interface type name (expected 'package/msg/Type')")
    return f"{match.group(1)}/{match.group(2) or 'msg'}/{match.group(3)}"


def _catalog_typestore() -> Typestore:
    store = get_typestore(Stores.ROS2_JAZZY)
    types = {}
    for name, text in TURTLESIM_MESSAGES.items():
        types.update(get_types_from_msg(text, name))
    for name, (request, response) in SERVICES.items():
        for part, text in (("Request", request), ("Response", response)):
            # rosbags files any parsed type under pkg/msg/: move it to the service's own name
            parsed = get_types_from_msg(text or _EMPTY_STRUCT, f"{name}_{part}")
            types.update({key.replace("/srv/msg/", "/srv/"): value for key, value in parsed.items()})
    # derived.py needs only rosbags; imported here because grader.interfaces' catalog imports this module
    from grader.interfaces.derived import action_types  # noqa: PLC0415
    for name, texts in ACTIONS.items():
        types.update(action_types(name, *(next(iter(get_types_from_msg(text, "pkg/msg/Part").values()))
                                          for text in texts)))
    store.register(types)
    return store


class Ros2Catalog:
    """Definitions, type hashes and validating CDR decoders for the ROS 2 types rosgrade handles.

    Same interface as ``MessageCatalog``: ``md5sum`` is the Jazzy RIHS01 type hash, which is what a ROS 2 node's
    ADVERTISE and SUBSCRIBE frames carry in place of ROS 1's md5sum.
    """

    profile = "ros2"
    schema_encoding = "ros2msg"
    message_encoding = "cdr"
    log_levels = frozenset({10, 20, 30, 40, 50})  # rcl_interfaces/msg/Log severities

    def __init__(self, extra: Mapping[str, tuple] | None = None, services: Iterable[str] = ()) -> None:
        """The built-in types, plus ``extra`` rosbags definitions (a submission's own, with the types rosidl
        derives from its services and actions) and the service types among them."""
        self._store = _catalog_typestore()
        if extra:
            self._store.register(dict(extra))
        self._services = frozenset(SERVICES) | frozenset(services) | frozenset(
            f"{action}_{part}" for action in ACTIONS for part in ("SendGoal", "GetResult"))
        self._msgdefs: dict[str, str] = {}
        self._hashes: dict[str, str] = {}
        self._hasher: Typestore | None = None

    @staticmethod
    def canonical(type_name: str) -> str:
        """The spelling this catalog records and compares: ``pkg/msg/Name``; ROS 1's ``rosgraph_msgs/Log`` (what a
        world declares its /rosout as, once for both flavours) is ROS 2's ``rcl_interfaces/msg/Log``."""
        return _ROS2_COUNTERPARTS.get(type_name) or ros2_type_name(type_name)

    def _name(self, type_name: str) -> str:
        name = ros2_type_name(type_name)
        if name not in self._store.fielddefs:
            raise RecordingError(f"unknown message type {type_name!r}")
        return name

    @property
    def typestore(self) -> Typestore:
        """The rosbags type store behind the catalog (to derive definitions and hashes from)."""
        return self._store

    def types(self) -> list[str]:
        return sorted(self._store.fielddefs)

    def known(self, type_name: str) -> bool:
        match = _TYPE_NAME.match(type_name)
        return match is not None and match.group(2) != "srv" and ros2_type_name(type_name) in self._store.fielddefs

    def definition(self, type_name: str) -> str:
        """The ``ros2msg`` schema text (the type, then every dependency after a ``MSG:`` line), as rosbag2 writes it."""
        name = self._name(type_name)
        cached = self._msgdefs.get(name)
        if cached is None:
            cached = self._msgdefs[name] = _msgdef(self._store, name)
        return cached

    def md5sum(self, type_name: str) -> str:
        """The type's RIHS01 hash (``RIHS01_<sha256>``), as Jazzy computes it."""
        name = self._name(type_name)
        cached = self._hashes.get(name)
        if cached is None:
            cached = self._hashes[name] = self._rosidl_hash(name)
        return cached

    def _rosidl_hash(self, name: str) -> str:
        if self._hasher is None:
            self._hasher = rihs01_hasher(self._store.fielddefs)
        return self._hasher.hash_rihs01(name)

    def message_class(self, type_name: str) -> type:
        return self._store.types[self._name(type_name)]

    def decode(self, type_name: str, data: bytes | bytearray | memoryview) -> object:
        """Parse CDR bytes as exactly one ``type_name`` message; RecordingError if they do not fit."""
        name = self._name(type_name)
        try:
            return self._store.deserialize_cdr(bytes(data), name)
        except Exception as exc:  # noqa: BLE001 - untrusted bytes: every parse failure is the sender's error
            raise RecordingError(f"{len(data)} bytes are not a valid {name} message: {_reason(exc)}") from None

    def encode(self, type_name: str, message: object) -> bytes:
        name = self._name(type_name)
        try:
            return bytes(self._store.serialize_cdr(message, name))
        except Exception as exc:  # noqa: BLE001 - rosbags raises assorted errors for a wrong object
            raise RecordingError(f"cannot serialize {type(message).__name__} as {name}: {exc}") from None

    @staticmethod
    def service_part(service_name: str, part: str) -> str:
        """The message type of a service's ``part`` ("Request" or "Response"): ``pkg/srv/Name_Request``."""
        name = _service_name(service_name)
        if not name:
            raise RecordingError(f"{service_name!r} is not a service type name (expected 'package/srv/Type')")
        return f"{name}_{part}"

    def known_service(self, service_name: str) -> bool:
        return _service_name(service_name) in self._services

    @staticmethod
    def service_type(service_name: str) -> str:
        """The spelling a client's call names a service type in: ``pkg/srv/Name`` (``pkg/Name`` is accepted)."""
        name = _service_name(service_name)
        if not name:
            raise RecordingError(f"{service_name!r} is not a service type name (expected 'package/srv/Type')")
        return name

    def service_md5sum(self, service_name: str) -> str:
        """The RIHS01 hash of a known service (what a ROS 2 client and server must agree on): the node library's,
        rosidl's hash of the service's request, response and event, for the services it has or was given; else its
        request's."""
        name = _service_name(service_name)
        if name not in self._services:
            raise RecordingError(f"unknown service type {service_name!r}")
        if name in NODE_SERVICE_HASHES:
            return NODE_SERVICE_HASHES[name]
        return self.md5sum(name if name in self._store.fielddefs else f"{name}_Request")


def _uint8_char(desc: tuple) -> tuple:
    node, detail = desc
    if node in (Nodetype.ARRAY, Nodetype.SEQUENCE):
        return (node, (_uint8_char(detail[0]), detail[1]))
    if node == Nodetype.BASE and detail[0] == "char":
        return (node, ("uint8", detail[1]))
    return desc


def rihs01_hasher(fielddefs: Mapping[str, tuple]) -> Typestore:
    """A type store of ``fielddefs`` (rosbags definitions) whose ``hash_rihs01`` gives rosidl's hashes:
    rosidl_adapter turns a .msg ``char`` into IDL ``uint8`` before the type description is hashed, where rosbags
    hashes it as a char (so rosbags' hash of std_msgs/msg/Char and of service_msgs/msg/ServiceEventInfo, which every
    service's hash covers, differ from a ROS 2 install's). ``hash_rihs01`` reads nothing but ``fielddefs``."""
    view = Typestore.__new__(Typestore)
    view.fielddefs = {name: (consts, [(fname, _uint8_char(desc)) for fname, desc in fields])
                      for name, (consts, fields) in fielddefs.items()}
    return view


def _spelled(type_name: str) -> str:
    """A field's type in schema text: ``pkg/Name`` for a message, the full name of a service's or action's part."""
    package, namespace, name = type_name.split("/")
    return f"{package}/{name}" if namespace == "msg" else type_name


def _msgdef(store: Typestore, type_name: str) -> str:
    """rosbags' ``generate_msgdef`` text (the type, then each dependency once, depth first, after a ``MSG:`` line),
    also for types that contain a service's or action's parts (an action's FeedbackMessage holds its Feedback),
    which rosbags' generator refuses to name."""
    try:
        return store.generate_msgdef(type_name, ros_version=2)[0]
    except AssertionError:
        pass
    subdefs: dict[str, str] = {}

    def text(name: str) -> str:
        consts, fields = store.fielddefs[name]
        lines = [f"{ctype} {cname}={value}" for cname, ctype, value in consts]
        for fname, (node, detail) in fields:
            if fname == "structure_needs_at_least_one_member":
                continue
            suffix = ""
            if node == Nodetype.ARRAY:
                (node, detail), count = detail
                suffix = f"[{count}]"
            elif node == Nodetype.SEQUENCE:
                (node, detail), count = detail
                suffix = f"[<={count}]" if count else "[]"
            if node == Nodetype.NAME:
                if detail not in subdefs:
                    subdefs[detail] = ""
                    subdefs[detail] = text(detail)
                lines.append(f"{_spelled(detail)}{suffix} {fname}")
            else:
                base, bound = detail
                lines.append(f"{base}{'<=' + str(bound) if bound else ''}{suffix} {fname}")
        return "\n".join([*lines, ""])

    own = text(type_name)
    return own + "".join(f"{'=' * 80}\nMSG: {_spelled(name)}\n{body}" for name, body in subdefs.items())


def _service_name(service_name: str) -> str:
    """``pkg/srv/Name`` for ``pkg/Name`` or ``pkg/srv/Name``; an action's own services keep ``pkg/action/``."""
    match = _TYPE_NAME.match(service_name)
    if match is None:
        return ""
    return f"{match.group(1)}/{'action' if match.group(2) == 'action' else 'srv'}/{match.group(3)}"


def _reason(exc: BaseException) -> str:
    text = str(exc) or type(exc).__name__
    if "unpack_from requires a buffer" in text or "index out of range" in text:
        return "too short, the data ends inside the message"
    return text


@lru_cache(maxsize=1)
def ros2_catalog() -> Ros2Catalog:
    """The process-wide ROS 2 catalog (building a type store takes ~70 ms)."""
    return Ros2Catalog()
