"""Container readers: MCAP (ROS 1 or ROS 2), ROS 1 bags and ROS 2 bags, loaded into one in-memory shape.

rosbags' MCAP reader rejects profile ``ros1`` and drops channel metadata (who published), so MCAP files are read
with mcap's streaming reader (which also gets the readable part of a truncated file) and decoded with a type store
built from the file's own schemas. Bags go through rosbags' AnyReader.
"""
from __future__ import annotations

import functools
import struct
from dataclasses import dataclass, field
from pathlib import Path

from mcap.exceptions import EndOfFile
from mcap.records import Channel as McapChannel
from mcap.records import Footer, Header, Metadata, Schema
from mcap.stream_reader import CRCValidationError
from rosbags.highlevel import AnyReader
from rosbags.interfaces import ConnectionExtRosbag1
from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from rosbags.typesys.store import Typestore

from grader import timing
from grader.recording.errors import RecordingError
from grader.recording.mcap_records import mcap_records
from grader.recording.messages import ros1_type_name

MCAP_MAGIC = b"\x89MCAP0\r\n"
BAG_MAGIC = b"#ROSBAG V2.0\n"
SQLITE_MAGIC = b"SQLite format 3\x00"


@dataclass(frozen=True)
class ChannelInfo:
    """One (topic, callerid, type) of a recording."""

    key: int
    topic: str
    type: str  # ROS 1 spelling
    store_type: str  # the type store's spelling, to decode with
    callerid: str
    latching: bool
    md5sum: str  # of the file's own definition; "" for ROS 2
    origin: str = ""  # 'world' | 'grader' | 'node' in rosgrade's recordings; "" when the file does not say


@dataclass
class Source:
    """A whole recording in memory: channels, messages in log-time order, metadata, and how to decode payloads."""

    format: str  # "mcap-ros1" | "mcap-ros2" | "rosbag1" | "rosbag2"
    encoding: str  # payload encoding: 'ros1' | 'cdr'
    typestore: Typestore
    channels: dict[int, ChannelInfo] = field(default_factory=dict)
    messages: list[tuple[int, int, bytes]] = field(default_factory=list)  # (channel key, log time ns, payload)
    metadata: dict[str, dict[str, str]] = field(default_factory=dict)
    truncated: str | None = None

    def definition(self, channel: ChannelInfo) -> str | None:
        """The file's own ``ros2msg`` text for the channel's type (None if the type store cannot give it)."""
        try:
            return self.typestore.generate_msgdef(channel.store_type, ros_version=2)[0]
        except Exception:  # noqa: BLE001 - a type the file defines oddly is simply not taken on the fast path
            return None

    def deserialize(self, data: bytes, channel: ChannelInfo) -> object:
        """Decode one payload with the file's types; RecordingError naming the topic when it does not parse."""
        try:
            if self.encoding == "ros1":
                return self.typestore.deserialize_ros1(data, channel.store_type)
            return self.typestore.deserialize_cdr(data, channel.store_type)
        except Exception as exc:  # noqa: BLE001 - untrusted bytes: any parse failure is a data error
            raise RecordingError(f"a message on {channel.topic} does not decode as {channel.type}: {exc}") from None


def _unreadable(path: Path, reason: str) -> RecordingError:
    return RecordingError(f"{path} is not a readable recording: {reason}")


def _describe(exc: BaseException) -> str:
    """An exception as one line; rosbags' reader errors speak for themselves, others get their class name."""
    text = str(exc)
    if not text:
        return type(exc).__name__
    return text if type(exc).__name__.endswith("ReaderError") else f"{type(exc).__name__}: {text}"


def load(path: str | Path) -> Source:
    """Read a recording of any supported format, telling the format by content rather than by name."""
    with timing.stage("reading recordings"):
        return _load(Path(path))


def _load(path: Path) -> Source:
    if not path.exists():
        raise _unreadable(path, "no such file or directory")
    if path.is_dir():
        return _load_anyreader(path, "rosbag2")
    try:
        with open(path, "rb") as file:
            head = file.read(64)
    except OSError as exc:
        raise _unreadable(path, exc.strerror or str(exc)) from None
    if not head:
        raise _unreadable(path, "the file is empty")
    if head.startswith(MCAP_MAGIC):
        profile = _mcap_profile(head)
        if profile in _MCAP_FLAVOURS or profile is None:  # None: too damaged to tell; our reader says how
            return _load_mcap(path, profile or "ros1")
        return _load_anyreader(path, "rosbag2", suffix=".mcap")
    if head.startswith(BAG_MAGIC):
        return _load_anyreader(path, "rosbag1", suffix=".bag")
    if head.startswith(SQLITE_MAGIC):
        return _load_anyreader(path, "rosbag2", suffix=".db3")
    raise _unreadable(path, "not an MCAP file, a ROS 1 bag or a ROS 2 bag")


def _mcap_profile(head: bytes) -> str | None:
    """The profile in the Header record that follows the magic, if the first bytes hold it."""
    try:
        opcode, _ = struct.unpack_from("<BQ", head, len(MCAP_MAGIC))
        (size,) = struct.unpack_from("<I", head, len(MCAP_MAGIC) + 9)
        start = len(MCAP_MAGIC) + 13
        return head[start : start + size].decode() if opcode == 0x01 else None
    except (struct.error, UnicodeDecodeError):
        return None


# MCAP profile -> (schema encoding, message encoding, Source.encoding, ROS version of the definitions).
_MCAP_FLAVOURS = {"ros1": ("ros1msg", "ros1", "ros1", 1), "ros2": ("ros2msg", "cdr", "cdr", 2)}


def _load_mcap(path: Path, profile: str) -> Source:
    """Read every record; on damage keep what came before and say where it stopped."""
    schemas: dict[int, Schema] = {}
    raw_channels: dict[int, McapChannel] = {}
    messages: list[tuple[int, int, bytes]] = []
    metadata: dict[str, dict[str, str]] = {}
    truncated: str | None = None
    seen_header = seen_footer = False
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise _unreadable(path, exc.strerror or str(exc)) from None
    try:
        for record in mcap_records(data, messages):
            if isinstance(record, McapChannel):
                raw_channels.setdefault(record.id, record)
            elif isinstance(record, Schema):
                schemas.setdefault(record.id, record)
            elif isinstance(record, Metadata):
                metadata[record.name] = dict(record.metadata)
            elif isinstance(record, Header):
                seen_header = True
            elif isinstance(record, Footer):
                seen_footer = True
    except Exception as exc:  # noqa: BLE001 - mcap raises assorted errors on damaged input
        truncated = _mcap_damage(exc)
    if not seen_header:
        raise _unreadable(path, truncated or "no MCAP header")
    if not seen_footer and truncated is None:
        truncated = "truncated (no footer)"
    if truncated is not None:
        if not messages:
            raise _unreadable(path, f"{truncated}, before any complete message")
        truncated = f"{truncated}; {len(messages)} messages before that were read"
    schema_encoding, message_encoding, encoding, version = _MCAP_FLAVOURS[profile]
    definitions = _definitions(path, schemas, schema_encoding)
    source = Source(f"mcap-{profile}", encoding, _typestore(path, definitions), metadata=metadata,
                    truncated=truncated)
    for channel in raw_channels.values():
        schema = schemas.get(channel.schema_id)
        if schema is None or schema.encoding != schema_encoding or channel.message_encoding != message_encoding:
            continue  # nothing to decode it with
        type_name, store_type = _names(schema.name)
        md5sum = _md5sum(definitions, store_type) if version == 1 else ""
        source.channels[channel.id] = ChannelInfo(
            channel.id,
            channel.topic,
            type_name,
            store_type,
            channel.metadata.get("callerid", ""),
            channel.metadata.get("latching", "false").lower() in ("true", "1"),
            md5sum,
            channel.metadata.get("origin", ""),
        )
    source.messages = sorted((m for m in messages if m[0] in source.channels), key=lambda m: m[1])
    return source


def _names(schema_name: str) -> tuple[str, str]:
    """(the type as the reader spells it, the type store's name) of a schema: ``pkg/Name`` and ``pkg/msg/Name`` for
    a message; a ROS 2 service part (``pkg/srv/Name_Request``) keeps its name, filed under ``pkg/srv/msg/``, as does
    an action's."""
    parts = schema_name.split("/")
    if len(parts) == 3 and parts[1] == "srv":
        return schema_name, f"{parts[0]}/srv/msg/{parts[2]}"
    if len(parts) == 3 and parts[1] == "action":  # an action's part (rosbags files it under its own name)
        return schema_name, schema_name
    type_name = ros1_type_name(schema_name)
    package, name = type_name.split("/")
    return type_name, f"{package}/msg/{name}"


def _ros1_spelling(msgtype: str) -> str:
    """``pkg/Name`` for ``pkg/msg/Name``; other interface names (ROS 2 services, actions) stay as they are."""
    parts = msgtype.split("/")
    return f"{parts[0]}/{parts[2]}" if len(parts) == 3 and parts[1] == "msg" else msgtype


def _mcap_damage(exc: BaseException) -> str:
    """Why the MCAP stream stopped, in words."""
    if isinstance(exc, (EndOfFile, struct.error)):
        return "truncated (the file ends inside a record)"
    if isinstance(exc, CRCValidationError):
        return "damaged (a chunk fails its checksum)"
    return f"damaged ({_describe(exc)})"


# (type name, definition text) of every schema of a file, in file order: what its type store is built from.
Definitions = tuple[tuple[str, str], ...]


def _definitions(path: Path, schemas: dict[int, Schema], encoding: str) -> Definitions:
    """The file's message definitions in ``encoding`` (ros1msg or ros2msg)."""
    try:
        return tuple((_names(schema.name)[0], schema.data.decode()) for schema in schemas.values()
                     if schema.encoding == encoding)
    except UnicodeDecodeError as exc:
        raise _unreadable(path, f"bad message definition ({_describe(exc)})") from None


def _typestore(path: Path, definitions: Definitions) -> Typestore:
    """A type store holding exactly the definitions the file carries."""
    try:
        return _shared_typestore(definitions)
    except Exception as exc:  # noqa: BLE001 - the schema text is file content, not code
        raise _unreadable(path, f"bad message definition ({_describe(exc)})") from None


# A run's recordings carry the same few definitions, whose parsing took as long as reading the messages: one store
# serves every file with the same definitions (nothing registers types in it afterwards).
@functools.lru_cache(maxsize=16)
def _shared_typestore(definitions: Definitions) -> Typestore:
    store = get_typestore(Stores.EMPTY)
    types = {}
    for type_name, text in definitions:
        types.update(get_types_from_msg(text, type_name))
    store.register(types)
    return store


@functools.lru_cache(maxsize=256)
def _md5sum(definitions: Definitions, store_type: str) -> str:
    """ROS 1 md5sum of a type as the file's own definitions give it."""
    return _shared_typestore(definitions).generate_msgdef(store_type, ros_version=1)[1]


def _load_anyreader(path: Path, fmt: str, suffix: str | None = None) -> Source:
    """ROS 1 bags and ROS 2 bags (folder, .db3, .mcap) through rosbags, which picks the reader by file suffix."""
    if suffix is not None and path.suffix != suffix:
        raise _unreadable(path, f"looks like a {fmt} file; name it *{suffix} to read it")
    try:
        with AnyReader([path]) as reader:
            source = Source(fmt, "cdr" if reader.is2 else "ros1", reader.typestore)
            keys = {}
            for key, connection in enumerate(reader.connections):
                keys[id(connection)] = key
                ext = connection.ext
                is_ros1 = isinstance(ext, ConnectionExtRosbag1)
                source.channels[key] = ChannelInfo(
                    key,
                    connection.topic,
                    _ros1_spelling(connection.msgtype),
                    connection.msgtype,
                    (ext.callerid or "") if is_ros1 else "",
                    bool(ext.latching) if is_ros1 else False,
                    connection.digest if is_ros1 else "",
                )
            source.messages = [
                (keys[id(connection)], t_ns, bytes(data)) for connection, t_ns, data in reader.messages()
            ]
    except RecordingError:
        raise
    except Exception as exc:  # noqa: BLE001 - rosbags raises assorted errors on damaged input
        raise _unreadable(path, _describe(exc)) from None
    source.messages.sort(key=lambda m: m[1])
    return source
