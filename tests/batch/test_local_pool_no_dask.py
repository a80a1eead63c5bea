"""The local process pool stays the default: a batch without --scheduler/--dask-workers never imports Dask."""
from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_a_local_batch_never_imports_dask(tmp_path: Path) -> None:
    klass = tmp_path / "class"
    for name in ("ann", "ben"):
        (klass / name / "scripts").mkdir(parents=True)
        (klass / name / "scripts" / "move_circle.py").write_text("import rospy\n")
    # A fresh interpreter (this one has imported distributed for the Dask tests), with the CLI tests' fake grading.
    code = textwrap.dedent(f"""
        import sys
        sys.path[:0] = [{str(ROOT)!r}, {str(ROOT / "tests")!r}]
        from faults.fake_rosgrade import install_fakes
        install_fakes()
        from grader.cli import main
        code = main(["batch", {str(klass)!r}, "--out", {str(tmp_path / "out")!r}, "-j", "2"])
        print(code, sorted(m for m in sys.modules if m.split(".")[0] in ("dask", "distributed")))
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert done.stdout.strip().splitlines()[-1] == "0 []", done.stdout + done.stderr
    assert (tmp_path / "out" / "grades.csv").is_file()
