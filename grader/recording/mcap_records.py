"""Read an MCAP file's records from memory with ``struct``: mcap's own stream reader costs ~10 µs a message.

Messages, the bulk of a recording, are appended to a list as ``(channel id, log time, payload)`` tuples; the few
other records (header, schemas, channels, metadata, footer) are parsed with mcap's record classes and yielded.
Damage is reported with mcap's exceptions (``EndOfFile``, ``CRCValidationError``, ...), so callers tell
"truncated" from "damaged" as they did with mcap's reader, and chunk and data-section checksums are checked.
"""
from __future__ import annotations

import struct
import zlib
from collections.abc import Iterator
from io import BytesIO

import zstandard
from mcap.data_stream import ReadDataStream
from mcap.exceptions import EndOfFile, InvalidMagic, RecordLengthLimitExceeded
from mcap.opcode import Opcode
from mcap.records import Channel, Chunk, DataEnd, Footer, Header, McapRecord, Metadata, Schema
from mcap.stream_reader import CRCValidationError

MAGIC = b"\x89MCAP0\r\n"
_RECORD = struct.Struct("<BQ")         # opcode, body length
_MESSAGE = struct.Struct("<HIQQ")      # channel id, sequence, log time, publish time
_CHUNK = struct.Struct("<QQQII")       # start time, end time, uncompressed size, uncompressed crc, compression len
_PARSED = {Opcode.HEADER: Header, Opcode.FOOTER: Footer, Opcode.SCHEMA: Schema, Opcode.CHANNEL: Channel,
           Opcode.METADATA: Metadata, Opcode.DATA_END: DataEnd}

Messages = list[tuple[int, int, bytes]]


class McapFormatError(Exception):
    """A chunk uses a compression this reader does not know."""


def _parse(opcode: int, body: bytes) -> McapRecord:
    return _PARSED[opcode].read(ReadDataStream(BytesIO(body)))


def _chunk_records(content: bytes, messages: Messages) -> Iterator[McapRecord]:
    """The schemas and channels of a chunk's records; its messages go to `messages` (the hot loop: kept inline)."""
    record, message, append = _RECORD.unpack_from, _MESSAGE.unpack_from, messages.append
    head, fixed, end, pos = _RECORD.size, _RECORD.size + _MESSAGE.size, len(content), 0
    while pos < end:
        if pos + head > end:
            raise EndOfFile()
        opcode, length = record(content, pos)
        stop = pos + head + length
        if stop > end:
            raise EndOfFile()
        if opcode == Opcode.MESSAGE:
            channel_id, _sequence, log_time, _publish = message(content, pos + head)
            append((channel_id, log_time, content[pos + fixed:stop]))
        elif opcode in (Opcode.SCHEMA, Opcode.CHANNEL):
            yield _parse(opcode, content[pos + head:stop])
        pos = stop


def _message(data: bytes, body: int, stop: int, messages: Messages) -> None:
    channel_id, _sequence, log_time, _publish = _MESSAGE.unpack_from(data, body)
    messages.append((channel_id, log_time, data[body + _MESSAGE.size:stop]))


def _chunk_content(data: bytes, body: int, stop: int) -> bytes:
    """The records of one Chunk record, decompressed and checked against its CRC."""
    _start, _end, size, crc, name_length = _CHUNK.unpack_from(data, body)
    pos = body + _CHUNK.size
    compression = data[pos:pos + name_length].decode()
    pos += name_length
    (length,) = struct.unpack_from("<Q", data, pos)
    pos += 8
    if pos + length > stop:
        raise EndOfFile()
    packed = data[pos:pos + length]
    if compression == "zstd":
        content = zstandard.ZstdDecompressor().decompress(packed, max_output_size=size)
    elif compression == "":
        content = packed
    else:
        raise McapFormatError(f"chunk compression {compression!r} is not supported")
    if crc != 0 and zlib.crc32(content) != crc:
        raise CRCValidationError(expected=crc, actual=zlib.crc32(content),
                                 record=Chunk(compression=compression, data=b"", message_end_time=_end,
                                              message_start_time=_start, uncompressed_crc=crc,
                                              uncompressed_size=size))
    return content


def mcap_records(data: bytes, messages: Messages) -> Iterator[McapRecord]:
    """Yield the non-message records of the MCAP file `data` in order, appending its messages to `messages`."""
    if not data.startswith(MAGIC):
        raise InvalidMagic(tuple(data[:len(MAGIC)]))
    limit = len(data)
    pos = len(MAGIC)
    while True:
        if pos + _RECORD.size > limit:
            raise EndOfFile()
        opcode, length = _RECORD.unpack_from(data, pos)
        if length > limit:
            raise RecordLengthLimitExceeded(opcode, length, limit)
        body, stop = pos + _RECORD.size, pos + _RECORD.size + length
        if stop > limit:
            raise EndOfFile()
        if opcode == Opcode.MESSAGE:
            _message(data, body, stop, messages)
        elif opcode == Opcode.CHUNK:
            content = _chunk_content(data, body, stop)
            yield from _chunk_records(content, messages)
        elif opcode in _PARSED:
            record = _parse(opcode, data[body:stop])
            if isinstance(record, DataEnd) and record.data_section_crc not in (0, zlib.crc32(data[:pos])):
                raise CRCValidationError(expected=record.data_section_crc, actual=zlib.crc32(data[:pos]),
                                         record=record)
            yield record
            if isinstance(record, Footer):
                if len(data) < stop + len(MAGIC):
                    raise EndOfFile()
                if data[stop:stop + len(MAGIC)] != MAGIC:
                    raise InvalidMagic(tuple(data[stop:stop + len(MAGIC)]))
                return
        pos = stop
