"""The run recorder: one deterministic MCAP per run, ROS 1 or ROS 2 after its catalog (same inputs, same bytes)."""
from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from types import TracebackType
from typing import BinaryIO

from mcap.writer import CompressionType, Writer

from grader import __version__
from grader.recording.errors import RecordingError
from grader.recording.fast_messages import MessageAppender
from grader.recording.messages import MessageCatalog, default_catalog
from grader.recording.ros2_messages import Ros2Catalog

# Metadata record the recorder adds when the size cap dropped messages.
CAP_METADATA = "rosgrade.recording"
# Who published a channel, as the grader knows it (channel metadata "origin"): the simulated world, the grader itself
# (its scripted driver), or a node. Unlike a callerid, a node cannot choose it.
ORIGINS = ("world", "grader", "node")


@dataclass(slots=True)
class _Channel:
    id: int
    type_name: str
    sequence: int = 0


def metadata_strings(name: str, values: Mapping[str, object]) -> dict[str, str]:
    """MCAP metadata values are strings: keep strings, JSON-encode everything else (sorted keys: deterministic)."""
    if not isinstance(name, str) or not name:
        raise RecordingError(f"metadata name must be a non-empty string, not {name!r}")
    out: dict[str, str] = {}
    for key, value in values.items():
        if not isinstance(key, str):
            raise RecordingError(f"metadata {name!r}: key {key!r} is not a string")
        try:
            out[key] = value if isinstance(value, str) else json.dumps(value, sort_keys=True)
        except (TypeError, ValueError) as exc:
            raise RecordingError(f"metadata {name!r}: value of {key!r} is not JSON-serializable: {exc}") from None
    return out


def _qos_yaml(transient_local: bool) -> str:
    """rosbag2's ``offered_qos_profiles`` text (rmw enum values, which every rosbag2 reads) for one reliable
    keep-last publisher; a transient-local one is ROS 2's latching."""
    return ("- history: 1\n  depth: 10\n  reliability: 1\n"
            f"  durability: {1 if transient_local else 2}\n"
            "  deadline:\n    sec: 0\n    nsec: 0\n  lifespan:\n    sec: 0\n    nsec: 0\n"
            "  liveliness: 1\n  liveliness_lease_duration:\n    sec: 0\n    nsec: 0\n"
            "  avoid_ros_namespace_conventions: false\n")


class Recorder:
    """Writes messages to an MCAP: one schema per type, one channel per (topic, callerid, origin), sim-time stamps.

    The catalog decides the flavour: ROS 1 (``ros1msg`` schemas, ``ros1`` payloads) or ROS 2 (``ros2msg``, ``cdr``,
    as rosbag2 writes them, so ``ros2 bag`` and Foxglove open the file).

    ``max_bytes`` caps the total payload; messages beyond it are dropped, counted and noted in the
    ``rosgrade.recording`` metadata record, so a flooding node cannot fill the disk.
    """

    def __init__(
        self,
        path: str | Path,
        metadata: Mapping[str, Mapping[str, object]] | None = None,
        *,
        max_bytes: int | None = None,
        chunk_size: int = 1 << 20,
        catalog: MessageCatalog | Ros2Catalog | None = None,
    ) -> None:
        self._path = Path(path)
        self._initial_metadata = {name: metadata_strings(name, values) for name, values in (metadata or {}).items()}
        self._max_bytes = max_bytes
        self._chunk_size = chunk_size
        self._catalog = catalog or default_catalog()
        self._file: BinaryIO | None = None
        self._writer: Writer | None = None
        self._closed = False
        self._schemas: dict[str, int] = {}
        self._channels: dict[tuple[str, str, str | None], _Channel] = {}
        self.message_count = 0
        self.payload_bytes = 0
        self.dropped = 0

    def __enter__(self) -> Recorder:
        self.open()
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.close()  # also after an error: what was recorded stays readable

    def open(self) -> None:
        """Create the file and write the header and the initial metadata."""
        if self._writer is not None or self._closed:
            raise RecordingError(f"recorder for {self._path} was already opened")
        try:
            self._file = open(self._path, "wb")  # noqa: SIM115 - closed in close()
        except OSError as exc:
            raise RecordingError(f"cannot create recording {self._path}: {exc.strerror or exc}") from None
        self._writer = Writer(self._file, chunk_size=self._chunk_size, compression=CompressionType.ZSTD)
        self._appender = MessageAppender(self._writer)
        self._writer.start(profile=self._catalog.profile, library=f"rosgrade {__version__}")
        for name, values in self._initial_metadata.items():
            self._writer.add_metadata(name, values)

    def _open_writer(self) -> Writer:
        if self._writer is None:
            state = "closed" if self._closed else "not open (use it as a context manager)"
            raise RecordingError(f"recorder for {self._path} is {state}")
        return self._writer

    def write(
        self,
        topic: str,
        type_name: str,
        payload: bytes | bytearray | memoryview,
        t_ns: int,
        callerid: str,
        latching: bool = False,
        origin: str | None = None,
    ) -> bool:
        """Record one message at sim time ``t_ns``; False when the size cap dropped it.

        The payload is not re-validated here: the grader decodes untrusted bytes once, on receipt.
        A channel keeps the latching flag of its first message. ``origin`` (one of ORIGINS; the grader always
        gives it) keeps what the world and the grader published in channels of their own, whatever name a node
        gave itself; a reader of a file with origins trusts only "world" channels for odometry and ground truth.
        """
        writer = self._open_writer()
        if not isinstance(t_ns, int) or t_ns < 0:
            raise RecordingError(f"message time must be a non-negative integer of nanoseconds, not {t_ns!r}")
        if not isinstance(payload, (bytes, bytearray, memoryview)):
            raise RecordingError(f"payload for {topic} must be bytes, not {type(payload).__name__}")
        if self._max_bytes is not None and self.payload_bytes + len(payload) > self._max_bytes:
            self.dropped += 1
            return False
        if origin is not None and origin not in ORIGINS:
            raise RecordingError(f"origin {origin!r} is not one of {', '.join(ORIGINS)}")
        key = (topic, callerid, origin)
        channel = self._channels.get(key)
        if channel is None:
            channel = self._channels[key] = self._register(writer, topic, type_name, callerid, latching, origin)
        elif channel.type_name != type_name and self._catalog.canonical(type_name) != channel.type_name:
            raise RecordingError(f"{callerid} wrote {type_name} on {topic}, which it recorded as {channel.type_name}")
        channel.sequence += 1
        self._appender.append(channel.id, channel.sequence, t_ns, bytes(payload))
        self.message_count += 1
        self.payload_bytes += len(payload)
        return True

    def _register(self, writer: Writer, topic: str, type_name: str, callerid: str, latching: bool,
                  origin: str | None) -> _Channel:
        if not topic.startswith("/"):
            raise RecordingError(f"topic {topic!r} is not a global name")
        catalog = self._catalog
        name = catalog.canonical(type_name)
        schema_id = self._schemas.get(name)
        if schema_id is None:
            definition = catalog.definition(name)
            schema_id = self._schemas[name] = writer.register_schema(
                name=name, encoding=catalog.schema_encoding, data=definition.encode()
            )
        if catalog.profile == "ros1":
            metadata = {"callerid": callerid, "md5sum": catalog.md5sum(name),
                        "latching": "1" if latching else "0"}  # the ROS 1 connection-header value, as bags keep it
        else:
            metadata = {"callerid": callerid, "offered_qos_profiles": _qos_yaml(latching),
                        "type_hash": catalog.md5sum(name)}
        if origin is not None:
            metadata["origin"] = origin
        channel_id = writer.register_channel(topic=topic, message_encoding=catalog.message_encoding,
                                             schema_id=schema_id, metadata=metadata)
        return _Channel(channel_id, name)

    def add_metadata(self, name: str, values: Mapping[str, object]) -> None:
        """Add a metadata record (e.g. ``rosgrade.run`` with the exit status at the end of a run)."""
        self._open_writer().add_metadata(name, metadata_strings(name, values))

    def close(self) -> None:
        """Write the summary and close the file; closing twice is harmless."""
        if self._writer is None:
            return
        writer, self._writer, self._closed = self._writer, None, True
        try:
            if self.dropped:
                note = {"max_bytes": self._max_bytes, "dropped": self.dropped}
                writer.add_metadata(CAP_METADATA, metadata_strings(CAP_METADATA, note))
            writer.finish()
        finally:
            assert self._file is not None
            self._file.close()
