"""The struct-based MCAP record reader gives exactly what mcap's own reader gives, and says so when it cannot."""
from __future__ import annotations

from pathlib import Path

import pytest
from mcap.exceptions import EndOfFile
from mcap.records import Channel, Footer, Header, Message, Metadata, Schema
from mcap.stream_reader import StreamReader

from grader.recording.mcap_records import McapFormatError, mcap_records
from recording_helpers import make_run, record


@pytest.fixture(scope="module", params=[1 << 20, 2048, 0], ids=["one_chunk", "small_chunks", "chunk_per_message"])
def written(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Path:
    return record(tmp_path_factory.mktemp("mcap") / "run.mcap", make_run(), chunk_size=request.param)


def _theirs(path: Path) -> tuple[list[tuple[int, int, bytes]], list[object]]:
    messages, others = [], []
    with open(path, "rb") as file:
        for record_ in StreamReader(file, validate_crcs=True).records:
            if isinstance(record_, Message):
                messages.append((record_.channel_id, record_.log_time, record_.data))
            elif isinstance(record_, (Header, Schema, Channel, Metadata, Footer)):
                others.append(record_)
    return messages, others


def test_messages_and_records_match_mcaps_reader(written: Path) -> None:
    messages: list[tuple[int, int, bytes]] = []
    ours = [r for r in mcap_records(written.read_bytes(), messages)
            if isinstance(r, (Header, Schema, Channel, Metadata, Footer))]
    theirs_messages, theirs = _theirs(written)
    assert messages == theirs_messages and len(messages) > 0
    assert ours == theirs


def test_a_file_cut_inside_a_record_is_end_of_file(written: Path) -> None:
    data = written.read_bytes()
    with pytest.raises(EndOfFile):
        list(mcap_records(data[: len(data) - 20], []))


def test_unknown_chunk_compression_is_refused(tmp_path: Path) -> None:
    data = record(tmp_path / "run.mcap", make_run()).read_bytes()
    with pytest.raises(McapFormatError, match="compression 'zstx'"):
        list(mcap_records(data.replace(b"zstd", b"zstx", 1), []))
