"""Nodes run with -B, so the grader writes the client libraries' bytecode for them."""
from __future__ import annotations

import importlib.util
import os
import shutil
from pathlib import Path

import pytest

import grader.nodelib as nodelib


def test_every_client_library_module_gets_its_bytecode(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    copy = tmp_path / "nodelib"
    shutil.copytree(nodelib.NODELIB, copy, ignore=shutil.ignore_patterns("__pycache__"))
    monkeypatch.setattr(nodelib, "NODELIB", copy)
    nodelib.precompile.__wrapped__()
    sources = list(copy.rglob("*.py"))
    assert sources and all(Path(importlib.util.cache_from_source(str(p))).is_file() for p in sources)


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write into a read-only folder")
def test_a_folder_it_may_not_write_is_left_as_it_is(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    copy = tmp_path / "nodelib"
    copy.mkdir()
    (copy / "module.py").write_text("X = 1\n")
    copy.chmod(0o555)
    monkeypatch.setattr(nodelib, "NODELIB", copy)
    try:
        nodelib.precompile.__wrapped__()  # quietly: the nodes then compile from source, as before
    finally:
        copy.chmod(0o755)
    assert [p.name for p in copy.iterdir()] == ["module.py"]
