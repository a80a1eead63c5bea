"""Parameter files and -p as real rclpy reads them: every case of nodes/param_file_cases.py run by the probe under
rosgrade's rclpy (one run) must give what real rclpy gave (param_files_real.json, recorded by record_param_files.py);
the grader-side reader gives the same overrides in process."""
from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import pytest

from grader.nodelib.common.rosgrade_param_files import ParamFileError, ParamSet
from grader.runtime.session import run
from grader.runtime.spec import Limits, NodeSpec, RunSpec
from sim import Scenario
from tests.params.record_param_files import (PROBE, RECORD, parse_output, record_real, stderr_lines,
                                             unavailable_reason)

_spec = importlib.util.spec_from_file_location("param_file_cases", PROBE.parent / "param_file_cases.py")
_cases = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_cases)
CASES = {case["id"]: case for case in _cases.CASES}
REAL = json.loads(RECORD.read_text(encoding="utf-8"))
RERECORD = "re-record with `python tests/params/record_param_files.py` where real rclpy is installed"


@pytest.fixture(scope="module")
def ours(tmp_path_factory) -> dict[str, dict]:
    """The probe's results under rosgrade: one turtlesim run (no sim time, like the real probe's run)."""
    tmp = tmp_path_factory.mktemp("param_files")
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=3.0),
                   nodes=(NodeSpec(script=PROBE, flavour="ros2"),), limits=Limits(wall_s=60.0, silent_wall_s=20.0))
    result = run(spec, tmp / "probe.mcap", tmp / "probe.log")
    from grader.recording import Recording
    lines = list(Recording.open(tmp / "probe.mcap").output_lines())
    assert result.nodes[0].status == "exited", result.nodes[0].message
    cases = parse_output("\n".join(line[2] for line in lines if line[1] == "stdout"))
    return {**cases, "stderr": stderr_lines("\n".join(line[2] for line in lines if line[1] == "stderr"))}


def test_the_record_covers_every_case() -> None:
    assert sorted(REAL["cases"]) == sorted(CASES), RERECORD
    assert len(CASES) >= 30


def test_the_record_is_what_real_rclpy_gives_today() -> None:
    """Where real rclpy is installed (CI builds it), the committed record must still be what it gives."""
    reason = unavailable_reason()
    if reason:
        pytest.skip(reason)
    live = record_real()
    assert (live["cases"], live["stderr"]) == (REAL["cases"], REAL["stderr"]), RERECORD


def test_what_is_logged_on_stderr_is_the_same(ours: dict[str, dict]) -> None:
    assert ours["stderr"] == REAL["stderr"]


@pytest.mark.parametrize("case_id", sorted(CASES))
def test_rosgrade_rclpy_reads_it_as_real_rclpy(ours: dict[str, dict], case_id: str) -> None:
    assert ours.get(case_id) == REAL["cases"][case_id]


def _type_name(value: object) -> str:
    """rclpy's Parameter.Type name of an override value."""
    if value is None:
        return "NOT_SET"
    if isinstance(value, list):
        return _type_name(value[0]) + "_ARRAY"
    return {bool: "BOOL", int: "INTEGER", float: "DOUBLE", str: "STRING"}[type(value)]


# Cases the grader side can replay alone: parameter files only, read for the node /talker.
FILE_ONLY = sorted(cid for cid, case in CASES.items()
                   if case.get("files") and case.get("args") in (_cases.PF, _cases.PF2) and "namespace" not in case
                   and "cli_args" not in case and "kwargs" not in case and not case.get("declare"))


@pytest.mark.parametrize("case_id", FILE_ONLY)
def test_the_grader_side_reader_gives_the_same_overrides(case_id: str) -> None:
    case, real = CASES[case_id], REAL["cases"][case_id]
    params = ParamSet()
    try:
        for text in case["files"]:
            params.read_text(text)
    except ParamFileError as exc:
        assert "init" in real and real["init"].endswith(f"Error: {exc}, at /project/src/rcl/arguments.c:415")
        return
    got = {name: [_type_name(value), repr(value)] for name, value in params.for_node("/talker").items()
           if name != "use_sim_time" or "use_sim_time" in case_id}
    assert got == real["overrides"]


def test_a_file_that_cannot_be_opened_says_so(tmp_path: Path) -> None:
    with pytest.raises(ParamFileError) as caught:
        ParamSet().read_file(str(tmp_path / "missing.yaml"))
    assert caught.value.problem == "Error opening YAML file"
