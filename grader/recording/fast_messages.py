"""Message records appended to an mcap Writer's open chunk without building a record object per message.

mcap's ``Writer.add_message`` builds a ``Message`` and writes it field by field (about 50 µs a message); a run writes
hundreds of thousands. ``MessageAppender`` does the same bookkeeping (file statistics, the chunk's time range and
message index) and writes the record with one struct, so the file is byte for byte what ``add_message`` writes (a
test compares them). It reaches into the Writer's private state, so it is used only when that state has the shape it
was written against (checked once per writer); otherwise every message goes through ``add_message``.
"""
from __future__ import annotations

import struct

from mcap.records import MessageIndex
from mcap.writer import Writer

_MESSAGE = struct.Struct("<BQHIQQ")  # opcode, record length, channel id, sequence, log time, publish time
_OPCODE_MESSAGE = 0x05
_HEAD = 2 + 4 + 8 + 8  # the record length counts the fields after it: these, then the data


class MessageAppender:
    """``append(channel_id, sequence, t_ns, data)`` equals ``writer.add_message(channel_id, t_ns, data, t_ns,
    sequence)`` in its effect on the file."""

    def __init__(self, writer: Writer) -> None:
        self._writer = writer
        self._stats = getattr(writer, "_Writer__statistics", None)
        self._chunk = getattr(writer, "_Writer__chunk_builder", None)
        self._finalize = getattr(writer, "_Writer__maybe_finalize_chunk", None)
        buffer = getattr(getattr(self._chunk, "record_writer", None), "_buffer", None)
        self.fast = (self._stats is not None and self._chunk is not None and callable(self._finalize)
                     and hasattr(buffer, "write") and hasattr(self._chunk, "message_indices")
                     and hasattr(self._stats, "channel_message_counts"))

    def append(self, channel_id: int, sequence: int, t_ns: int, data: bytes) -> None:
        if not self.fast:
            self._writer.add_message(channel_id=channel_id, log_time=t_ns, data=data, publish_time=t_ns,
                                     sequence=sequence)
            return
        stats, chunk = self._stats, self._chunk
        if stats.message_count == 0:
            stats.message_start_time = t_ns
        elif t_ns < stats.message_start_time:
            stats.message_start_time = t_ns
        if t_ns > stats.message_end_time:
            stats.message_end_time = t_ns
        stats.channel_message_counts[channel_id] += 1
        stats.message_count += 1
        if chunk.num_messages == 0:
            chunk.message_start_time = t_ns
        elif t_ns < chunk.message_start_time:
            chunk.message_start_time = t_ns
        if t_ns > chunk.message_end_time:
            chunk.message_end_time = t_ns
        buffer = chunk.record_writer._buffer
        index = chunk.message_indices.get(channel_id)
        if not index:
            index = chunk.message_indices[channel_id] = MessageIndex(channel_id=channel_id, records=[])
        index.records.append((t_ns, buffer.tell()))
        chunk.num_messages += 1
        buffer.write(_MESSAGE.pack(_OPCODE_MESSAGE, _HEAD + len(data), channel_id, sequence, t_ns, t_ns))
        buffer.write(data)
        self._finalize()
