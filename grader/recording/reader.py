"""`Recording`: a run's recording (ours, a ROS 1 bag or a ROS 2 bag) as the numpy arrays the metrics score."""
from __future__ import annotations

import copy
import heapq
import json
from collections.abc import Collection, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from grader.recording import memo as memos
from grader.recording.errors import RecordingError
from grader.recording.messages import MessageCatalog, default_catalog
from grader.recording.ros2_messages import ros2_catalog
from grader.recording.serialize import decode_odometry_pose_twist, decode_twist
from grader.recording.serialize_cdr import decode_odometry_pose_twist_cdr
from grader.recording.series import (
    CommandSeries,
    LogLine,
    OutputLine,
    TimeSeries,
    TopicInfo,
    TransformSeries,
    seconds,
    yaw_from_quaternion,
)
from grader.recording.sources import ChannelInfo, Source, load

GROUND_TRUTH_TOPIC = "/ground_truth/odom"
DEFAULT_ODOMETRY_TOPIC = "/odom"
SIM_CALLERID = "/gazebo"
OUTPUT_TOPICS = {"/rosgrade/stdout": "stdout", "/rosgrade/stderr": "stderr", "/rosout": "rosout"}
LOG = "rosgraph_msgs/Log"
LOG2 = "rcl_interfaces/Log"  # ROS 2's /rosout
OUTPUT_TYPES = ("std_msgs/String", LOG, LOG2)
# ROS 2 severities on the ROS 1 scale that log metrics use (1 DEBUG, 2 INFO, 4 WARN, 8 ERROR, 16 FATAL).
_ROS1_LEVEL = {10: 1, 20: 2, 30: 4, 40: 8, 50: 16}
TF_TOPICS = ("/tf", "/tf_static")
ODOMETRY = "nav_msgs/Odometry"
TWIST = "geometry_msgs/Twist"
TWIST_STAMPED = "geometry_msgs/TwistStamped"  # ROS 2 Jazzy's velocity command
COMMAND_TYPES = (TWIST, TWIST_STAMPED)

Vec3 = tuple[float, float, float]
# One decoded pose/twist row: stamp ns, x y z qx qy qz qw, linear, angular.
_PoseTwist = tuple[int, tuple[float, ...], Vec3, Vec3]


def _ros2_definition(type_name: str) -> str | None:
    """Jazzy's ``ros2msg`` text of a type, or None when rosgrade does not know it."""
    try:
        return ros2_catalog().definition(type_name)
    except RecordingError:
        return None


def _json_or_text(value: str) -> Any:
    """Metadata values are JSON where the writer encoded them, plain text otherwise."""
    try:
        return json.loads(value)
    except (ValueError, RecursionError):
        return value


class Recording:
    """Read-only view of one recording; open with `Recording.open`."""

    def __init__(self, path: Path, source: Source | None, catalog: MessageCatalog, memo: memos.FileMemo) -> None:
        """A view of the file at ``path`` through its ``memo``; ``source`` is the file loaded, or None until something
        not in the memo is asked for."""
        self.path = path
        self._loaded = source
        self._catalog = catalog
        self._fast: dict[int, bool] = {}  # channel key -> whether the struct decoders apply (see _fast_decoding)
        self._index: dict[int, list[int]] | None = None  # channel key -> positions of its messages, made on first use
        self._memo = memo
        self.format = memo.format
        self.truncated = memo.truncated  # why the file ends early, or None
        self.metadata: dict[str, dict[str, Any]] = copy.deepcopy(memo.metadata)

    @classmethod
    def open(cls, path: str | Path, *, allow_truncated: bool = True) -> Recording:
        """Load our MCAP, a ROS 1 ``.bag``, a ROS 2 bag folder, ``.db3`` or ROS 2 MCAP.

        A truncated MCAP gives what could be read, with ``truncated`` saying why; ``allow_truncated=False``
        makes that an error instead. A file read before and unchanged since gives what was read then (see memo.py).
        """
        path = Path(path)
        found = memos.identity(path)
        memo = memos.find(path, found)
        source = None
        if memo is None:
            source = load(path)
            memo = memos.FileMemo(found, source.format, source.truncated, {
                name: {key: _json_or_text(value) for key, value in values.items()}
                for name, values in source.metadata.items()
                if name == "rosgrade" or name.startswith("rosgrade.")
            })
            if found is not None:
                memos.keep(path, memo)
        recording = cls(path, source, default_catalog(), memo)
        if recording.truncated and not allow_truncated:
            raise RecordingError(f"{path} is not a readable recording: {recording.truncated}")
        return recording

    @property
    def _source(self) -> Source:
        if self._loaded is None:
            self._loaded = load(self.path)
        return self._loaded

    # -- generic access ---------------------------------------------------------------------------------------

    def _channels(self, topic: str | None = None, type_name: str | None = None) -> list[ChannelInfo]:
        return [
            c
            for c in self._source.channels.values()
            if (topic is None or c.topic == topic) and (type_name is None or c.type == type_name)
        ]

    @memos.remembered
    def topics(self) -> list[TopicInfo]:
        """Every (topic, callerid) with its type and message count, sorted by topic."""
        counts = dict.fromkeys(self._source.channels, 0)
        for key, _, _ in self._source.messages:
            counts[key] += 1
        infos = [TopicInfo(c.topic, c.type, c.callerid, counts[c.key], c.origin)
                 for c in self._source.channels.values()]
        return sorted(infos)

    def _marks_origin(self) -> bool:
        """Whether the file says who published each channel (rosgrade's recordings do)."""
        return any(c.origin for c in self._source.channels.values())

    def _world_channels(self, topic: str | None = None, type_name: str | None = None) -> list[ChannelInfo]:
        """Channels the simulated world published, when the file says; every matching channel otherwise (a bag
        recorded on a robot). A node's channel on the same topic, whatever its callerid, is never among them."""
        channels = self._channels(topic, type_name)
        return [c for c in channels if c.origin == "world"] if self._marks_origin() else channels

    def _raw(self, channels: list[ChannelInfo]) -> Iterator[tuple[ChannelInfo, int, bytes]]:
        """The messages of ``channels`` in recorded order, found through a per-channel index (a scoring run asks
        for a handful of topics in a file of tens of thousands of messages)."""
        if self._index is None:
            self._index = {}
            for position, (key, _, _) in enumerate(self._source.messages):
                self._index.setdefault(key, []).append(position)
        lists = [self._index.get(c.key, []) for c in channels]
        positions = lists[0] if len(lists) == 1 else heapq.merge(*lists)
        wanted = {c.key: c for c in channels}
        messages = self._source.messages
        for position in positions:
            key, t_ns, data = messages[position]
            yield wanted[key], t_ns, data

    def messages(self, topic: str, callerid: str | None = None) -> Iterator[tuple[int, object]]:
        """(log time ns, decoded message) for every message on ``topic`` in time order (rosbags message objects)."""
        channels = [c for c in self._channels(topic) if callerid is None or c.callerid == callerid]
        for channel, t_ns, data in self._raw(channels):
            yield t_ns, self._source.deserialize(data, channel)

    def world_messages(self, topic: str) -> Iterator[tuple[int, object]]:
        """Like ``messages``, but only what the simulated world published on ``topic`` (every channel of a bag that
        does not say who published what): a node's look-alike channel, whatever name it took, is left out."""
        for channel, t_ns, data in self._raw(self._world_channels(topic)):
            yield t_ns, self._source.deserialize(data, channel)

    def world_topics(self, type_name: str) -> list[str]:
        """The topics of ``type_name`` the world published (see ``world_messages``), sorted."""
        return sorted({c.topic for c in self._world_channels(type_name=type_name)})

    def messages_on(self, topics: Collection[str]) -> Iterator[tuple[str, int, object]]:
        """(topic, log time ns, decoded message) for every message on any of ``topics``, in the order they were
        recorded (which keeps the order of messages on different topics at one time, e.g. successive service calls)."""
        for channel, t_ns, data in self._raw([c for c in self._channels() if c.topic in topics]):
            yield channel.topic, t_ns, self._source.deserialize(data, channel)

    def _fast_decoding(self, channel: ChannelInfo) -> bool:
        """Whether the channel's payloads have exactly the layout the struct decoders read (decided once per
        channel): ROS 1 bytes with the catalog's md5sum, or CDR of the file's own definition when it is Jazzy's."""
        fast = self._fast.get(channel.key)
        if fast is None:
            if self._source.encoding == "ros1":
                fast = channel.md5sum == self._catalog.md5sum(channel.type)
            else:
                fast = self._source.definition(channel) == _ros2_definition(channel.type)
            self._fast[channel.key] = fast
        return fast

    # -- odometry ---------------------------------------------------------------------------------------------

    def odometry_topic(self) -> str | None:
        """The robot's odometry topic: named in the metadata, else the simulator's (/odom first), else /odom or any."""
        odometry = [c for c in self._world_channels(type_name=ODOMETRY) if c.topic != GROUND_TRUTH_TOPIC]
        names = {c.topic for c in odometry}
        info = self.metadata.get("rosgrade", {})
        robot = info.get("robot")
        for named in (info.get("odometry_topic"), robot.get("odometry_topic") if isinstance(robot, dict) else None):
            if named in names:
                return named
        from_sim = {c.topic for c in odometry if c.callerid == SIM_CALLERID}
        for pool in (from_sim, names):  # a node may publish its own /odom next to the simulator's
            if DEFAULT_ODOMETRY_TOPIC in pool:
                return DEFAULT_ODOMETRY_TOPIC
            if pool:
                return min(pool)
        return None

    @memos.remembered
    def odometry(self, topic: str | None = None) -> TimeSeries:
        """Pose and body twist from the robot's odometry topic (or ``topic``), stamped by the message headers."""
        topic = topic or self.odometry_topic()
        if topic is None:
            raise RecordingError(f"{self.path} has no nav_msgs/Odometry topic")
        series = self._pose_twist(topic)
        if series is None:
            raise RecordingError(f"{self.path} has no nav_msgs/Odometry messages on {topic}")
        return series

    @memos.remembered
    def ground_truth(self) -> TimeSeries | None:
        """The true world pose and body twist, or None when the recording has none (e.g. a real robot's bag)."""
        return self._pose_twist(GROUND_TRUTH_TOPIC)

    def _pose_twist(self, topic: str) -> TimeSeries | None:
        channels = self._world_channels(topic, ODOMETRY)
        if not channels:
            return None
        rows: list[_PoseTwist] = []
        log_ns: list[int] = []
        for channel, t_ns, data in self._raw(channels):
            if not self._fast_decoding(channel):
                rows.append(self._generic_odometry(data, channel))
            elif self._source.encoding == "ros1":
                rows.append(decode_odometry_pose_twist(data))
            else:
                rows.append(decode_odometry_pose_twist_cdr(data))
            log_ns.append(t_ns)
        stamps = [row[0] for row in rows]
        # Unstamped odometry (all zero headers) falls back to when it was recorded.
        t = seconds(stamps if any(stamps) else log_ns)
        pose = np.array([row[1] for row in rows], dtype=np.float64).reshape(-1, 7)
        linear = np.array([row[2] for row in rows], dtype=np.float64).reshape(-1, 3)
        angular = np.array([row[3] for row in rows], dtype=np.float64).reshape(-1, 3)
        return TimeSeries(
            t=t,
            x=pose[:, 0],
            y=pose[:, 1],
            yaw=yaw_from_quaternion(pose[:, 3], pose[:, 4], pose[:, 5], pose[:, 6]),
            vx=linear[:, 0],
            wz=angular[:, 2],
            topic=topic,
        )

    def _generic_odometry(self, data: bytes, channel: ChannelInfo) -> _PoseTwist:
        msg: Any = self._source.deserialize(data, channel)
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        v, w = msg.twist.twist.linear, msg.twist.twist.angular
        t_ns = msg.header.stamp.sec * 1_000_000_000 + msg.header.stamp.nanosec
        return t_ns, (p.x, p.y, p.z, q.x, q.y, q.z, q.w), (v.x, v.y, v.z), (w.x, w.y, w.z)

    # -- commands, transforms, output -------------------------------------------------------------------------

    def command_topics(self) -> list[str]:
        """Topics carrying velocity commands: named in the metadata, else every Twist or TwistStamped topic."""
        named = self.metadata.get("rosgrade", {}).get("command_topics")
        if isinstance(named, list) and all(isinstance(t, str) for t in named):
            return list(named)
        return sorted({c.topic for c in self._channels() if c.type in COMMAND_TYPES})

    @memos.remembered
    def commands(self, topic: str | None = None) -> CommandSeries:
        """Every Twist (or TwistStamped) on the command topics (or ``topic``) with who sent it, at record time."""
        topics = {topic} if topic else set(self.command_topics())
        channels = [c for c in self._channels() if c.type in COMMAND_TYPES and c.topic in topics]
        t_ns: list[int] = []
        values: list[tuple[Vec3, Vec3]] = []
        topic_names: list[str] = []
        callerids: list[str] = []
        origins: list[str] = []
        for channel, stamp, data in self._raw(channels):
            fast = self._source.encoding == "ros1" and self._fast_decoding(channel)
            values.append(decode_twist(data) if fast else self._generic_twist(data, channel))
            t_ns.append(stamp)
            topic_names.append(channel.topic)
            callerids.append(channel.callerid)
            origins.append(channel.origin)
        return CommandSeries(
            t=seconds(t_ns),
            linear=np.array([v[0] for v in values], dtype=np.float64).reshape(-1, 3),
            angular=np.array([v[1] for v in values], dtype=np.float64).reshape(-1, 3),
            topic=np.array(topic_names, dtype=object),
            callerid=np.array(callerids, dtype=object),
            origin=np.array(origins, dtype=object) if self._marks_origin() else None,
        )

    def _generic_twist(self, data: bytes, channel: ChannelInfo) -> tuple[Vec3, Vec3]:
        msg: Any = self._source.deserialize(data, channel)
        if channel.type == TWIST_STAMPED:
            msg = msg.twist
        return (msg.linear.x, msg.linear.y, msg.linear.z), (msg.angular.x, msg.angular.y, msg.angular.z)

    @memos.remembered
    def transforms(self, topic: str | None = None) -> TransformSeries:
        """Every transform on /tf and /tf_static (or ``topic``), one row per TransformStamped, by header stamp."""
        stamps: list[int] = []
        frames: list[str] = []
        children: list[str] = []
        values: list[tuple[float, ...]] = []
        for tf_topic in (topic,) if topic else TF_TOPICS:
            for _, msg in self.messages(tf_topic):
                for tr in getattr(msg, "transforms", ()):
                    stamps.append(tr.header.stamp.sec * 1_000_000_000 + tr.header.stamp.nanosec)
                    frames.append(tr.header.frame_id)
                    children.append(tr.child_frame_id)
                    v, r = tr.transform.translation, tr.transform.rotation
                    values.append((v.x, v.y, v.z, r.x, r.y, r.z, r.w))
        table = np.array(values, dtype=np.float64).reshape(-1, 7)
        return TransformSeries(
            t=seconds(stamps),
            frame_id=np.array(frames, dtype=object),
            child_frame_id=np.array(children, dtype=object),
            translation=table[:, :3],
            rotation=table[:, 3:],
        )

    @memos.remembered
    def output_lines(self) -> list[OutputLine]:
        """What the node printed (/rosgrade/stdout, /rosgrade/stderr) and logged (/rosout), in time order."""
        channels = [c for c in self._source.channels.values() if c.topic in OUTPUT_TOPICS and c.type in OUTPUT_TYPES]
        lines = []
        for channel, t_ns, data in self._raw(channels):
            msg: Any = self._source.deserialize(data, channel)
            text = msg.msg if channel.type in (LOG, LOG2) else msg.data
            lines.append(OutputLine(t_ns / 1e9, OUTPUT_TOPICS[channel.topic], text))
        return lines

    @memos.remembered
    def rosout(self) -> list[LogLine]:
        """Every /rosout message with its level and origin (node name, file, function, line), in time order."""
        lines = []
        for t_ns, msg in self.messages("/rosout"):
            m: Any = msg
            level = int(m.level)
            if self._source.encoding == "cdr":
                level = _ROS1_LEVEL.get(level, level)
            lines.append(LogLine(t_ns / 1e9, level, m.name, m.msg, m.file, m.function, int(m.line)))
        return lines
