"""ROS 1 message types rosgrade knows: schema text, md5sum and strict decoding of untrusted bytes.

Built on rosbags' Noetic type store (plus tf2_msgs, turtlesim and std_srvs, which it lacks), so definitions and md5sums are
exactly what `gendeps --cat` and genpy give without a ROS install.
"""
from __future__ import annotations

import hashlib
import re
from collections.abc import Mapping
from functools import lru_cache

from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from rosbags.typesys.store import Typestore

from grader.recording.errors import RecordingError

_TYPE_NAME = re.compile(r"^([A-Za-z][A-Za-z0-9_]*)/(?:msg/)?([A-Za-z][A-Za-z0-9_]*)$")

# Packages the Noetic store holds that are not ROS 1 message packages (ROS 2 time types used internally).
_HIDDEN_PACKAGES = frozenset({"builtin_interfaces"})

_EXTRA_TYPES = {
    "tf2_msgs/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
    "turtlesim/Pose": "float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\nfloat32 angular_velocity\n",
    "turtlesim/Color": "uint8 r\nuint8 g\nuint8 b\n",
}

# std_srvs and turtlesim services as (request, response) definitions; all primitive-only, so their md5 text is the
# text itself.
_SERVICES = {
    "std_srvs/Empty": ("", ""),
    "std_srvs/Trigger": ("", "bool success\nstring message"),
    "std_srvs/SetBool": ("bool data", "bool success\nstring message"),
    "turtlesim/Kill": ("string name", ""),
    "turtlesim/SetPen": ("uint8 r\nuint8 g\nuint8 b\nuint8 width\nuint8 off", ""),
    "turtlesim/Spawn": ("float32 x\nfloat32 y\nfloat32 theta\nstring name", "string name"),
    "turtlesim/TeleportAbsolute": ("float32 x\nfloat32 y\nfloat32 theta", ""),
    "turtlesim/TeleportRelative": ("float32 linear\nfloat32 angular", ""),
}


def ros1_type_name(type_name: str) -> str:
    """``pkg/Name`` for ``pkg/Name`` or ``pkg/msg/Name``; RecordingError for anything else."""
    match = _TYPE_NAME.match(type_name)
    if match is None:
        raise RecordingError(f"{type_name!r} is not a ROS message type name (expected 'package/Type')")
    return f"{match.group(1)}/{match.group(2)}"


def _store_name(type_name: str) -> str:
    """rosbags' spelling ``pkg/msg/Name``."""
    package, name = ros1_type_name(type_name).split("/")
    return f"{package}/msg/{name}"


def _catalog_typestore() -> Typestore:
    """Noetic types plus the extra message and service types rosgrade uses."""
    store = get_typestore(Stores.ROS1_NOETIC)
    types = {}
    for name, text in _EXTRA_TYPES.items():
        types.update(get_types_from_msg(text, _store_name(name)))
    for name, (request, response) in _SERVICES.items():
        types.update(get_types_from_msg(request, _store_name(name + "Request")))
        types.update(get_types_from_msg(response, _store_name(name + "Response")))
    store.register(types)
    return store


class MessageCatalog:
    """Definitions, md5sums and validating decoders for the ROS 1 message types rosgrade handles."""

    profile = "ros1"
    schema_encoding = "ros1msg"
    message_encoding = "ros1"
    log_levels = frozenset({1, 2, 4, 8, 16})  # rosgraph_msgs/Log severities

    @staticmethod
    def canonical(type_name: str) -> str:
        """The spelling this catalog records and compares: ``pkg/Name``."""
        return ros1_type_name(type_name)

    def __init__(self, extra: Mapping[str, tuple] | None = None, services: Mapping[str, str] | None = None) -> None:
        """The built-in types, plus ``extra`` rosbags definitions (a submission's own) and md5sums of the service
        types among them (``pkg/Name``)."""
        self._store = _catalog_typestore()
        if extra:
            self._store.register(dict(extra))
        self._service_md5s = {name: hashlib.md5((request + response).encode()).hexdigest()
                              for name, (request, response) in _SERVICES.items()}
        self._service_md5s.update(services or {})
        self._msgdefs: dict[str, tuple[str, str]] = {}
        self._store_names: dict[str, str] = {}  # any accepted spelling -> rosbags name, for the hot decode path

    @property
    def typestore(self) -> Typestore:
        """The rosbags type store behind the catalog (to derive definitions and md5 texts from)."""
        return self._store

    def types(self) -> list[str]:
        """All known message type names, ROS 1 spelling, sorted."""
        return sorted(
            ros1_type_name(name) for name in self._store.fielddefs if name.split("/")[0] not in _HIDDEN_PACKAGES
        )

    def known(self, type_name: str) -> bool:
        """Whether ``type_name`` (any string) is a message type of this catalog."""
        match = _TYPE_NAME.match(type_name)
        return (
            match is not None
            and match.group(1) not in _HIDDEN_PACKAGES
            and f"{match.group(1)}/msg/{match.group(2)}" in self._store.fielddefs
        )

    def _msgdef(self, type_name: str) -> tuple[str, str]:
        """(full concatenated definition, md5sum), computed once per type."""
        name = ros1_type_name(type_name)
        cached = self._msgdefs.get(name)
        if cached is None:
            if not self.known(name):
                raise RecordingError(f"unknown message type {name!r}")
            cached = self._msgdefs[name] = self._store.generate_msgdef(_store_name(name), ros_version=1)
        return cached

    def _store_type(self, type_name: str) -> str:
        """rosbags' name of a known type, resolved once per spelling."""
        name = self._store_names.get(type_name)
        if name is None:
            self._msgdef(type_name)
            name = self._store_names[type_name] = _store_name(type_name)
        return name

    def definition(self, type_name: str) -> str:
        """The ``ros1msg`` schema text: the type's definition, then every dependency after a ``MSG:`` line."""
        return self._msgdef(type_name)[0]

    def md5sum(self, type_name: str) -> str:
        """The ROS 1 md5sum of the type."""
        return self._msgdef(type_name)[1]

    def message_class(self, type_name: str) -> type:
        """The rosbags dataclass for the type (to build messages in tests and tools)."""
        return self._store.types[self._store_type(type_name)]

    def decode(self, type_name: str, data: bytes | bytearray | memoryview) -> object:
        """Parse ROS 1 bytes as exactly one ``type_name`` message; RecordingError if they do not fit exactly."""
        store_type = self._store_type(type_name)
        try:
            return self._store.deserialize_ros1(data, store_type)
        except Exception as exc:  # noqa: BLE001 - untrusted bytes: every parse failure is the sender's error
            raise RecordingError(
                f"{len(data)} bytes are not a valid {ros1_type_name(type_name)} message: {_reason(exc)}"
            ) from None

    def encode(self, type_name: str, message: object) -> bytes:
        """ROS 1 bytes of a rosbags message object (generic and slow; hot paths use `serialize`)."""
        store_type = self._store_type(type_name)
        try:
            return bytes(self._store.serialize_ros1(message, store_type))
        except Exception as exc:  # noqa: BLE001 - rosbags raises assorted errors for a wrong object
            raise RecordingError(f"cannot serialize {type(message).__name__} as {type_name}: {exc}") from None

    @staticmethod
    def service_part(service_name: str, part: str) -> str:
        """The message type of a service's ``part`` ("Request" or "Response"): ``pkg/NameRequest``."""
        return ros1_type_name(service_name) + part

    def known_service(self, service_name: str) -> bool:
        """Whether ``service_name`` (any string) is a service type of this catalog."""
        match = _TYPE_NAME.match(service_name)
        return match is not None and f"{match.group(1)}/{match.group(2)}" in self._service_md5s

    @staticmethod
    def service_type(service_name: str) -> str:
        """The spelling a client's call names a service type in: ``pkg/Name``."""
        return ros1_type_name(service_name)

    def service_md5sum(self, service_name: str) -> str:
        """The ROS 1 md5sum of a known service (md5 of request and response md5 texts)."""
        try:
            return self._service_md5s[ros1_type_name(service_name)]
        except KeyError:
            raise RecordingError(f"unknown service type {service_name!r}") from None


def _reason(exc: BaseException) -> str:
    """A short reason for a failed parse, without rosbags' internals."""
    text = str(exc) or type(exc).__name__
    if "size mismatch" in text:
        return "trailing bytes after a complete message"
    if "unpack_from requires a buffer" in text:
        return "too short, the data ends inside the message"
    return text.split(": ", 1)[1] if text.startswith("Could not deserialize") and ": " in text else text


@lru_cache(maxsize=1)
def default_catalog() -> MessageCatalog:
    """The process-wide catalog (building a type store takes ~70 ms)."""
    return MessageCatalog()
