"""Record what real rclpy (Jazzy, the venv .ci/ros2-venv builds) makes of every parameter-file case: the target that
test_param_files_conformance.py holds rosgrade's rclpy to, where CI has no real ROS 2.

Usage: python tests/params/record_param_files.py [OUT.json]  (default: tests/params/param_files_real.json).
The probe (nodes/param_file_probe.py) runs once under the venv's python, on a DDS domain of its own.
"""
from __future__ import annotations

import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "conformance_ros2"))

from real_ros2 import DomainLock, ros2_env, unavailable_reason, venv_python  # noqa: E402

PROBE = HERE / "nodes" / "param_file_probe.py"
RECORD = HERE / "param_files_real.json"


class RecordError(Exception):
    """Real rclpy could not be run, or the probe did not finish."""


def parse_output(stdout: str) -> dict[str, dict]:
    """The probe's per-case results, by case id; RecordError when it did not reach its END line."""
    lines = stdout.splitlines()
    if "END" not in lines:
        raise RecordError("the probe stopped before its last case:\n" + stdout[-2000:])
    return {case["id"]: case for case in (json.loads(line[5:]) for line in lines if line.startswith("CASE "))}


def record_real() -> dict:
    """Run the probe under real rclpy; its results and the rclpy version they came from."""
    reason = unavailable_reason()
    if reason:
        raise RecordError(reason)
    lock = DomainLock()
    try:
        home = Path(tempfile.mkdtemp(prefix="rosgrade-param-files-"))
        env = ros2_env(lock.domain_id, home)
        env["PYTHONPATH"] = str(PROBE.parent)
        python = str(venv_python())
        version = subprocess.run([python, "-c", "import importlib.metadata as m; print(m.version('rclpy'))"],
                                 env=env, capture_output=True, text=True, timeout=60).stdout.strip()
        proc = subprocess.run([python, str(PROBE)], env=env, capture_output=True, text=True, timeout=300)
    finally:
        lock.close()
    return {"rclpy": version or "unknown", "cases": parse_output(proc.stdout), "stderr": stderr_lines(proc.stderr)}


def stderr_lines(text: str) -> list[str]:
    """What the probe logged on stderr, its time stamps taken out (real rclpy logs wall time, rosgrade sim time)."""
    return [re.sub(r"^\[(\w+)\] \[[0-9.]+\]", r"[\1] [T]", line) for line in text.splitlines() if line.strip()]


def dump(record: dict) -> str:
    """The record as JSON with one case a line, so that a re-recording's diff shows the cases that changed."""
    cases = ",\n".join(f"  {json.dumps(k)}: {json.dumps(v, sort_keys=True)}" for k, v in sorted(record["cases"].items()))
    return (f'{{\n "rclpy": {json.dumps(record["rclpy"])},\n "stderr": {json.dumps(record["stderr"])},\n'
            f' "cases": {{\n{cases}\n }}\n}}\n')


def main(argv: list[str]) -> int:
    out = Path(argv[1]) if len(argv) > 1 else RECORD
    try:
        record = record_real()
    except (RecordError, subprocess.TimeoutExpired) as exc:
        print(f"could not record: {exc}", file=sys.stderr)
        return 1
    out.write_text(dump(record), encoding="utf-8")
    print(f"{len(record['cases'])} cases from real rclpy {record['rclpy']} written to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
