"""The nodes a launch file starts through ExecuteProcess `ros2 run` get the argv and parameter files they get under
real ROS 2 Jazzy launch and ros2run (recorded by record_real_exec.py into cases/real_exec_records.json): `ros2 run`'s
own arguments, unchanged, a shell command line split as the shell splits it."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from grader.launch.ros2_specs import ros2_node_specs
from grader.runtime.spec import NodeSpec, file_arg
from grader.workspace import read_workspace

pytestmark = pytest.mark.slow  # two confined evaluations of the launch file, about 1 s

CASES = Path(__file__).resolve().parent / "cases"
RECORDS = json.loads((CASES / "real_exec_records.json").read_text())


def _received(spec: NodeSpec) -> dict:
    """What the node receives, as the record has it: its executable's name, its argv, its parameter files."""
    files = dict(spec.files)
    executable = spec.entry.executable if spec.entry is not None else spec.script.name
    argv = [executable, *("<params-file>" if word in {file_arg(name) for name in files} else word
                          for word in spec.args)]
    return {"argv": argv, "params_files": [files[name].decode() for name, _ in spec.files]}


@pytest.mark.parametrize("case_id", sorted(RECORDS))
def test_nodes_started_by_ros2_run_receive_what_they_receive_under_real_launch(case_id: str) -> None:
    case = RECORDS[case_id]
    launch = CASES / "ws" / "course_pkg" / "launch" / case["file"]
    specs, findings, _ = ros2_node_specs(launch, read_workspace(CASES / "ws"), case["args"], None)
    assert sorted((_received(spec) for spec in specs), key=json.dumps) == case["started"]
    assert not [f for f in findings if "did not run" in f or "not run" in f]
