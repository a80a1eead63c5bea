"""What stays the same when the grader runs on another CPU: recordings byte for byte, grades field for field.

Run by hand (`python3 tests/determinism/cross_cpu.py FOLDER_OR_SCRIPT... [--task T]`) it checks each path three
ways and prints what differs:

* ``native``: this machine as it is (numpy and OpenBLAS pick their kernels for this CPU, AVX-512 where it has it);
* ``numpy-baseline``: numpy limited to its baseline kernels (NPY_DISABLE_CPU_FEATURES) and OpenBLAS to its
  Haswell kernels, in the grader and, through the environment it hands on, nowhere else (nodes get a clean one);
* ``haswell``: the grader under ``qemu-x86_64 -cpu Haswell`` (Debian's qemu-user), a CPU without AVX-512, so that
  MuJoCo, numpy and OpenBLAS all run another CPU's code paths. The nodes still run natively: qemu-user does not
  follow the grader's exec of the node's interpreter;
* ``sandybridge`` (asked for with ``--ways``): the same on a CPU with AVX but neither AVX2 nor FMA.

The test beside it (test_cross_cpu.py) runs one TurtleBot task the first and last way.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
QEMU = shutil.which("qemu-x86_64")
# Feature names numpy 2.x dispatches on x86_64 beyond its X86_V2 baseline; numpy ignores names it does not know.
NUMPY_BASELINE = "X86_V3 X86_V4 AVX512_ICL AVX512_SPR AVX512F AVX512CD AVX512_SKX AVX512_CLX AVX512_CNL AVX2 FMA3"
WAYS = {
    "native": ([], {}),
    "numpy-baseline": ([], {"NPY_DISABLE_CPU_FEATURES": NUMPY_BASELINE, "OPENBLAS_CORETYPE": "Haswell"}),
    "haswell": ([QEMU or "qemu-x86_64", "-cpu", "Haswell"], {}),
    # AVX without AVX2 and FMA: the oldest CPU MuJoCo's wheel runs on; glibc's libm then takes its non-FMA paths.
    "sandybridge": ([QEMU or "qemu-x86_64", "-cpu", "SandyBridge"], {}),
}


# Measured quantities come from numpy and BLAS kernels picked per CPU (a sum's order, FMA): the same value to about
# 1e-15 relative, not always to the bit. Points, verdicts and feedback must be the same.
MEASURED_REL = 1e-9


@dataclass
class Comparison:
    """Two checks of the same submission, file by file and criterion by criterion."""

    same_files: list[str] = field(default_factory=list)
    different_files: list[str] = field(default_factory=list)
    different_grades: list[str] = field(default_factory=list)  # points, pass/fail, feedback, task status
    last_bits: list[str] = field(default_factory=list)  # measured values within MEASURED_REL, not the same bits


# An emulated CPU runs the grader 10-30 times slower: a run's wall-clock budget (120 s) is raised to an hour, in
# every way alike, so that what is compared is what the CPU computes, not what the budget cut short.
_CHECK = ("import dataclasses, sys, grader.grading as g; spec = g.RunSpec; "
          "g.RunSpec = lambda **kw: spec(**{**kw, 'limits': dataclasses.replace(kw['limits'], wall_s=3600.0)}); "
          "from grader.cli import main; sys.exit(main(sys.argv[1:]))")


def check(target: Path, out: Path, way: str, tasks: list[str]) -> float:
    """Grade target one way into out; the wall seconds it took."""
    prefix, extra = WAYS[way]
    env = {**os.environ, **extra, "PYTHONWARNINGS": "ignore"}
    command = [*prefix, sys.executable, "-c", _CHECK, "check", str(target), "-j", "1", "--out", str(out),
               *[arg for task in tasks for arg in ("--task", task)]]
    started = time.monotonic()
    done = subprocess.run(command, cwd=REPO, env=env, capture_output=True, text=True, timeout=3600)
    if done.returncode not in (0, 1):
        raise RuntimeError(f"{way} check of {target} failed ({done.returncode}): {done.stderr[-2000:]}")
    return time.monotonic() - started


def _grades(report: Path) -> tuple[dict[str, object], dict[str, object]]:
    """Every task's and criterion's points, verdict and feedback, and apart from them every measured value, keyed by
    where they are."""
    data = json.loads(report.read_text())
    grades: dict[str, object] = {"score": data["score"], "max_score": data["max_score"]}
    measured: dict[str, object] = {}
    for task in data["tasks"]:
        grades[f"{task['id']}.score"] = (task["score"], task["max_score"], task["status"])
        for criterion in task["criteria"]:
            where = f"{task['id']}.{criterion['id']}"
            for key in ("score", "passed", "feedback"):
                grades[f"{where}.{key}"] = criterion[key]
            for key, value in criterion["measured"].items():
                measured[f"{where}.measured.{key}"] = value
    return grades, measured


def _close(first: object, second: object) -> bool:
    if isinstance(first, float) and isinstance(second, float):
        return abs(first - second) <= MEASURED_REL * max(abs(first), abs(second))
    return first == second


def compare(first: Path, second: Path) -> Comparison:
    """Recordings and logs byte for byte, grades field for field, of two report folders of the same check."""
    result = Comparison()
    for path in sorted(first.rglob("*")):
        if path.suffix in (".mcap", ".log") and path.is_file():
            name = str(path.relative_to(first))
            other = second / name
            same = other.is_file() and other.read_bytes() == path.read_bytes()
            (result.same_files if same else result.different_files).append(name)
    (ours, our_measures), (theirs, their_measures) = _grades(first / "report.json"), _grades(second / "report.json")
    result.different_grades = [key for key in sorted(ours.keys() | theirs.keys()) if ours.get(key) != theirs.get(key)]
    for key in sorted(our_measures.keys() | their_measures.keys()):
        mine, other = our_measures.get(key), their_measures.get(key)
        if mine != other:
            (result.last_bits if _close(mine, other) else result.different_grades).append(key)
    return result


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("targets", nargs="+", type=Path)
    parser.add_argument("--task", action="append", default=[])
    parser.add_argument("--out", type=Path, default=Path("/tmp/rosgrade-cross-cpu"))
    parser.add_argument("--ways", default="native,numpy-baseline,haswell", help=f"of {', '.join(WAYS)}")
    args = parser.parse_args()
    ways = args.ways.split(",")
    if QEMU is None and any(WAYS[way][0] for way in ways):
        print("qemu-x86_64 not found (Debian: apt install qemu-user): the emulated ways are left out")
        ways = [way for way in ways if not WAYS[way][0]]
    print(f"{'submission':40} {'way':15} {'wall s':>7} {'same files':>10} {'differ':>6} {'grades differ':>13} "
          f"{'last bits':>9}")
    for target in args.targets:
        base = args.out / target.name
        for way in ways:
            wall = check(target.resolve(), base / way, way, args.task)
            if way == ways[0]:
                print(f"{target.name:40} {way:15} {wall:7.1f}")
                continue
            result = compare(base / ways[0], base / way)
            print(f"{target.name:40} {way:15} {wall:7.1f} {len(result.same_files):10} "
                  f"{len(result.different_files):6} {len(result.different_grades):13} {len(result.last_bits):9}")
            for name in result.different_files:
                print(f"    differs: {name}")
            for key in result.different_grades:
                print(f"    grade differs: {key}")
            for key in result.last_bits:
                print(f"    measured value differs in its last bits: {key}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
