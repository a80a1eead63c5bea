"""`rosgrade launch --json` against what real ROS 2 Jazzy launch started for the same launch files (recorded by
record_real.py into cases/real_records.json): processes in start order, argv, parameter-file contents, LogInfo
texts, errors."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from grader.launch.ros2_cli import args_text
from grader.launch.ros2_eval import evaluate
from grader.workspace import read_workspace

pytestmark = pytest.mark.slow  # 29 sandboxed evaluations, about 8 s

CASES = Path(__file__).resolve().parent / "cases"
RUNS = json.loads((CASES / "runs.json").read_text())
RECORDS = json.loads((CASES / "real_records.json").read_text())


def _cmd(cmd: list[str]) -> list[str]:
    """argv with the install prefix and parameter-file paths taken out (they differ by machine and run)."""
    out = []
    for index, word in enumerate(cmd):
        if index > 0 and cmd[index - 1] == "--params-file":
            out.append("<params-file>")
        elif index == 0 and "/lib/" in word:
            out.append(word[word.index("/lib/") + 1:])
        else:
            out.append(word)
    return out


def _error(text: str | None) -> str | None:
    if text is None:
        return None
    text = re.sub(r"searching: \[.*?\]", "searching: [...]", text)
    text = re.sub(r"'<prefix>/lib/|'/rosgrade/install/[^/]+/lib/", "'lib/", text)
    return text.split(", expanded from")[0]


def _real(case_id: str) -> dict:
    record = RECORDS[case_id]
    return {"processes": [{"name": p["name"].rsplit("-", 1)[0], "cmd": _cmd(p["cmd"]), "params": p["params_files"]}
                          for p in record["processes"]],
            "error": _error(record["error"]), "logs": record["logs"]}


def _ours(case: dict) -> dict:
    workspace = read_workspace(CASES / "ws")
    path = CASES / "ws" / "course_pkg" / "launch" / case["file"]
    result = evaluate(path, workspace, list(case["args"].items())).result
    processes = [{"name": p["name"].rsplit("-", 1)[0], "cmd": _cmd(p["cmd"]),
                  "params": [f["content"] for f in p.get("params_files", [])]} for p in result["processes"]]
    error = result["error"]["message"] if result["error"] else None
    return {"processes": processes, "error": _error(error), "logs": [log["text"] for log in result["logs"]]}


@pytest.fixture(scope="module")
def ours() -> dict[str, dict]:
    return {case["id"]: _ours(case) for case in RUNS}


def test_records_cover_every_case() -> None:
    assert sorted(set(RECORDS) - {"show_args"}) == sorted(case["id"] for case in RUNS)
    assert len({case["file"] for case in RUNS}) >= 20


@pytest.mark.parametrize("case_id", [case["id"] for case in RUNS])
def test_matches_real_launch(ours: dict[str, dict], case_id: str) -> None:
    assert ours[case_id] == _real(case_id)


@pytest.mark.parametrize("file", sorted(RECORDS["show_args"]))
def test_show_args_prints_what_ros2_launch_prints(file: str) -> None:
    real = RECORDS["show_args"][file]
    result = evaluate(CASES / "ws" / "course_pkg" / "launch" / file, read_workspace(CASES / "ws"), [],
                      show_args=True).result
    if real.startswith("error: "):
        assert result.get("error"), result
    else:
        assert args_text(result["arguments"]) == real
