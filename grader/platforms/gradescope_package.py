"""Builds the Gradescope autograder zip: setup.sh, run_autograder and an sdist of this rosgrade checkout."""
from __future__ import annotations

import io
import json
import shlex
import tarfile
import zipfile
from collections.abc import Sequence
from pathlib import Path

import grader
from grader.platforms.gradescope import UNFINISHED_MESSAGE, gradescope_failure
from grader.rubricfile import RubricFile

SOURCE_ITEMS = ("pyproject.toml", "README.md", "LICENSE", "sim", "grader", "rubrics")
SKIP_PARTS = {"__pycache__", ".pytest_cache"}
SKIP_SUFFIXES = {".pyc", ".pyo"}
DEFAULT_TIMEOUT_S = 540  # Gradescope stops everything at 10 min and then shows nothing; stop first and report.
VENV = "/opt/rosgrade"
_FIXED_MTIME = 1_700_000_000  # reproducible archives: same checkout, same bytes
EXTRA_RUBRICS = "rubrics_extra"  # the instructor's own rubric files, in the zip and beside the submission

MIN_PYTHON = (3, 11)  # MuJoCo 4.0.0 and tomllib; Gradescope's default Ubuntu 22.04 image has only 3.10

_SETUP_SH = """#!/usr/bin/env bash
# Runs once while Gradescope builds the autograder image: a Python >= {min_python}, bubblewrap, and rosgrade in {venv}.
# Gradescope's Ubuntu 22.04 image has Python 3.10 (python3.11 comes from the universe archive); 24.04 has 3.12.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update
# bubblewrap confines each student node (no network, private /tmp, read-only system) where the container allows it.
apt-get install -y --no-install-recommends ca-certificates bubblewrap python3 python3-venv

# The first interpreter new enough for rosgrade, or nothing.
suitable_python() {{
  local candidate
  for candidate in python3.13 python3.12 python3.11 python3; do
    if command -v "$candidate" >/dev/null 2>&1 &&
       "$candidate" -c 'import sys; sys.exit(sys.version_info < {min_tuple})' 2>/dev/null; then
      command -v "$candidate"
      return 0
    fi
  done
  return 1
}}

PYTHON=$(suitable_python) || {{
  apt-get install -y --no-install-recommends python3.11 python3.11-venv
  PYTHON=$(suitable_python) || {{ echo "setup.sh: no Python >= {min_python} could be installed" >&2; exit 1; }}
}}
echo "setup.sh: using $PYTHON ($("$PYTHON" --version))"
"$PYTHON" -m venv {venv}
{venv}/bin/pip install --no-cache-dir --upgrade pip
{venv}/bin/pip install --no-cache-dir /autograder/source/{sdist}
# Build matplotlib's font cache now instead of during the timed grading run.
MPLCONFIGDIR={venv}/mpl {venv}/bin/python -c "import matplotlib; matplotlib.use('Agg'); import matplotlib.pyplot"
# Student nodes run as unprivileged users (rosgrade gives each node its own uid), which must be able to read
# the interpreter and the client library they import.
chmod -R a+rX {venv}
"""

_RUN_AUTOGRADER = """#!/usr/bin/env bash
# Grades /autograder/submission with rosgrade and always leaves a valid /autograder/results/results.json.
# rosgrade runs as root so that each student node runs as its own unprivileged uid (inside bubblewrap when the
# container allows it): the node can neither read this autograder's files nor touch the results rosgrade writes.
set -uo pipefail
RESULTS=/autograder/results/results.json
mkdir -p /autograder/results
chmod o= /autograder/source /autograder/results /autograder/submission_metadata.json 2>/dev/null
WORK=$(mktemp -d /tmp/rosgrade.XXXXXX)
chmod 755 "$WORK"
cp -r /autograder/submission "$WORK/submission"
if [ -d /autograder/source/{extra} ]; then cp -r /autograder/source/{extra} "$WORK/{extra}"; fi
chmod -R a+rX "$WORK/submission"
cp -r {venv}/mpl "$WORK/mpl"
cd "$WORK"
# rosgrade writes an 'unfinished' results.json first, so a kill at the time limit still explains itself.
timeout --kill-after=15 {timeout} env HOME="$WORK" MPLCONFIGDIR="$WORK/mpl" \\
  {venv}/bin/rosgrade check "$WORK/submission" {tasks}{rubrics} --out "$WORK/out" --gradescope "$WORK/results.json"
echo "rosgrade exit code: $?"
if {venv}/bin/python -c 'import json, sys; json.load(open(sys.argv[1]))' "$WORK/results.json" 2>/dev/null; then
  cp "$WORK/results.json" "$RESULTS"
else
  cat > "$RESULTS" <<'JSON'
{fallback}
JSON
fi
exit 0
"""

_README = """# rosgrade Gradescope autograder

Tasks: {task_list}. Built from rosgrade {version}.

Upload this zip as the autograder ("Zip file upload"; the Ubuntu 22.04 or 24.04 base image). Default limits are
enough: half a vCPU, 768 MB, 10 minutes.

- setup.sh finds a Python >= 3.11 (installing python3.11 from Ubuntu's archive on 22.04, whose own Python is 3.10),
  installs bubblewrap, and makes a virtual environment in {venv} with rosgrade from the bundled sdist and its PyPI
  dependencies (mujoco-core, numpy, matplotlib, pydantic, mcap, rosbags, rich, pyyaml). It runs once, when the image
  is built.
- run_autograder copies the submission to a scratch folder and runs `rosgrade check` as root; rosgrade runs each
  student node as its own unprivileged user (inside bubblewrap where the container allows it; the report says which
  isolation a run had), so student code never runs as root and cannot read /autograder/source or change the
  results. rosgrade is stopped after {timeout} s, a minute before Gradescope's own limit, so students get an
  explanation instead of a silent zero; a results.json that is missing or invalid is replaced by one that explains
  the failure.

Expected time per submission: the simulation is deterministic and runs much faster than real time (sim time is
charged per call, not waited for), so grading time is Python start-up plus the simulated seconds of each scenario
divided by the real-time factor. Measure it on your machine with `rosgrade bench --reference reference_solutions`
and double it for Gradescope's half vCPU; keep the total under {timeout} s. Memory stays well below 768 MB
(one grader process with MuJoCo and matplotlib, plus one student node process at a time).
"""


class PackageError(Exception):
    """The autograder zip cannot be built (no source checkout to bundle)."""


def source_root() -> Path:
    """The checkout this rosgrade runs from (its sdist is what Gradescope installs)."""
    root = Path(grader.__file__).resolve().parents[1]
    if not (root / "pyproject.toml").is_file():
        raise PackageError(f"gradescope-package needs a rosgrade source checkout; no pyproject.toml in {root}")
    return root


def _source_files(root: Path) -> list[Path]:
    files: list[Path] = []
    for item in SOURCE_ITEMS:
        path = root / item
        candidates = [path] if path.is_file() else sorted(p for p in path.rglob("*") if p.is_file()) if path.is_dir() else []
        files += [
            p for p in candidates
            if not SKIP_PARTS.intersection(p.relative_to(root).parts) and p.suffix not in SKIP_SUFFIXES
            and not any(part.endswith(".egg-info") for part in p.relative_to(root).parts)
        ]
    return files


def build_sdist(root: Path) -> tuple[str, bytes]:
    """A source distribution (name, bytes) of the checkout: what `pip install` builds on Gradescope."""
    base = f"rosgrade-{grader.__version__}"
    buffer = io.BytesIO()
    with tarfile.open(fileobj=buffer, mode="w:gz", format=tarfile.PAX_FORMAT) as archive:
        members = {f"{base}/{p.relative_to(root).as_posix()}": p.read_bytes() for p in _source_files(root)}
        # pyproject names README.md as the readme; an sdist without it would not build.
        members.setdefault(f"{base}/README.md", b"# rosgrade\n")
        members[f"{base}/PKG-INFO"] = f"Metadata-Version: 2.1\nName: rosgrade\nVersion: {grader.__version__}\n".encode()
        for name in sorted(members):
            info = tarfile.TarInfo(name)
            info.size, info.mtime, info.mode = len(members[name]), _FIXED_MTIME, 0o644
            archive.addfile(info, io.BytesIO(members[name]))
    return f"{base}.tar.gz", buffer.getvalue()


def build_autograder_zip(task_ids: Sequence[str], out: Path, timeout_s: int = DEFAULT_TIMEOUT_S,
                         max_score: float | None = None, extra_rubrics: Sequence[RubricFile] = ()) -> Path:
    """Write the autograder zip to out and return its path; max_score is what a run that never finished is out of;
    extra_rubrics (instructors' own tasks) go inside it."""
    if not task_ids:
        raise PackageError("name the tasks to grade with --task")
    sdist_name, sdist = build_sdist(source_root())
    fallback = json.dumps(gradescope_failure(UNFINISHED_MESSAGE, max_score), indent=2)
    tasks = " ".join(f"--task {shlex.quote(t)}" for t in task_ids)
    extra = {f"{EXTRA_RUBRICS}/{i}/{name}": data for i, rubric in enumerate(extra_rubrics)
             for name, data in ((f"{rubric.task_id}.toml", rubric.text), *rubric.plugins)}
    rubrics = "".join(f' --rubric "$WORK/{EXTRA_RUBRICS}/{i}/{r.task_id}.toml"' for i, r in enumerate(extra_rubrics))
    files: dict[str, str | bytes] = {
        "setup.sh": _SETUP_SH.format(venv=VENV, sdist=sdist_name, min_python=".".join(map(str, MIN_PYTHON)),
                                     min_tuple=str(MIN_PYTHON)),
        "run_autograder": _RUN_AUTOGRADER.format(venv=VENV, timeout=timeout_s, tasks=tasks, fallback=fallback,
                                                 rubrics=rubrics, extra=EXTRA_RUBRICS),
        "README.md": _README.format(task_list=", ".join(task_ids), version=grader.__version__, venv=VENV, timeout=timeout_s),
        **extra,
    }
    out.parent.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(out, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for name, text in files.items():
            info = zipfile.ZipInfo(name, date_time=(2024, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if name in ("setup.sh", "run_autograder") else 0o644) << 16
            archive.writestr(info, text, compress_type=zipfile.ZIP_DEFLATED)
        info = zipfile.ZipInfo(sdist_name, date_time=(2024, 1, 1, 0, 0, 0))
        info.external_attr = 0o644 << 16
        archive.writestr(info, sdist)
    return out
