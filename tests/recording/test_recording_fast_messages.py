"""The fast message path writes exactly the bytes mcap's own Writer.add_message writes."""
from __future__ import annotations

import io

from mcap.writer import CompressionType, Writer

from grader.recording.fast_messages import MessageAppender


def _file(fast: bool, messages: list[tuple[int, int, int, bytes]], chunk_size: int) -> bytes:
    stream = io.BytesIO()
    writer = Writer(stream, chunk_size=chunk_size, compression=CompressionType.ZSTD)
    writer.start(profile="ros1", library="test")
    schema = writer.register_schema(name="std_msgs/String", encoding="ros1msg", data=b"string data")
    channels = [writer.register_channel(topic=f"/t{i}", message_encoding="ros1", schema_id=schema) for i in range(3)]
    appender = MessageAppender(writer)
    assert appender.fast  # the installed mcap has the shape the fast path expects
    for channel, sequence, t_ns, data in messages:
        if fast:
            appender.append(channels[channel], sequence, t_ns, data)
        else:
            writer.add_message(channel_id=channels[channel], log_time=t_ns, data=data, publish_time=t_ns,
                               sequence=sequence)
    writer.finish()
    return stream.getvalue()


def _messages() -> list[tuple[int, int, int, bytes]]:
    out = []
    for i in range(3000):
        # out-of-order times too (a latched message replayed late), empty and large payloads
        t_ns = 1_000_000 * i - (5_000_000 if i % 97 == 0 else 0)
        out.append((i % 3, i, max(t_ns, 0), bytes([i % 251]) * (i % 700)))
    return out


def test_fast_path_bytes_equal_add_message_across_many_chunks() -> None:
    messages = _messages()
    assert _file(True, messages, chunk_size=4096) == _file(False, messages, chunk_size=4096)


def test_fast_path_bytes_equal_add_message_in_one_chunk() -> None:
    messages = _messages()[:50]
    assert _file(True, messages, chunk_size=1 << 20) == _file(False, messages, chunk_size=1 << 20)


def test_a_writer_of_another_shape_falls_back_to_add_message() -> None:
    class Plain:
        def __init__(self) -> None:
            self.calls = []

        def add_message(self, **kwargs) -> None:
            self.calls.append(kwargs)

    plain = Plain()
    appender = MessageAppender(plain)  # type: ignore[arg-type]
    appender.append(3, 7, 42, b"x")
    assert not appender.fast
    assert plain.calls == [{"channel_id": 3, "log_time": 42, "data": b"x", "publish_time": 42, "sequence": 7}]
