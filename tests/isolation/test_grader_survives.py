"""`rosgrade check` of a node that writes to the grader's stdout and terminal, then kills its parent: in every
isolation mode the run either ends with a complete report, or (rlimits only) fails without one (rosgrade killed, or
its grading worker killed and rosgrade exiting 2 with rosgrade-error.txt), never half-written."""
from __future__ import annotations

import json
import shutil
import signal
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path

import pytest

from grader.runtime import confine

REPO = Path(__file__).resolve().parents[2]
CAP = confine.detect()
# Modes in which the node cannot signal the grader: the report must always be written.
GRADER_OUT_OF_REACH = CAP.namespaces or CAP.mode == "uid"

PARRICIDE = """\
import os, signal, rospy
from geometry_msgs.msg import Twist
rospy.init_node("move_circle")
for path in ("/proc/%d/fd/1" % os.getppid(), "/dev/tty"):
    try:
        with open(path, "w") as handle:
            handle.write("PWNED\\n")
    except OSError:
        pass
os.write(1, b"PWNED on its own stdout\\n")
try:
    os.kill(os.getppid(), signal.SIGKILL)
except OSError as exc:
    print("kill:", exc)
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    pub.publish(Twist())
    rate.sleep()
"""


# As root without namespaces, an interpreter only root can read makes rosgrade refuse to run the node at all.
REFUSES = CAP.mode == "uid" and not confine.readable_by_others(Path(sys.executable))


@pytest.fixture(scope="module")
def checked() -> Iterator[tuple[subprocess.CompletedProcess, Path]]:
    folder = Path(tempfile.mkdtemp(prefix="rosgrade-test-"))
    folder.chmod(0o755)  # pytest's folders are private to their user: the node's own uid must read this one
    (folder / "move_circle.py").write_text(PARRICIDE)
    out = folder / "out"
    done = subprocess.run([sys.executable, "-m", "grader.cli", "check", str(folder), "--task", "move_circle",
                           "--out", str(out), "--json"], cwd=REPO, capture_output=True, text=True, timeout=600,
                          stdin=subprocess.DEVNULL, start_new_session=True)
    yield done, out
    shutil.rmtree(folder, ignore_errors=True)


def _grader_killed(done: subprocess.CompletedProcess) -> bool:
    """The node killed its parent: rosgrade itself (SIGKILL), or the grading worker `rosgrade check` forks per
    scenario on a machine with two cores or more (rosgrade then stops with exit code 2 and rosgrade-error.txt)."""
    return done.returncode == -signal.SIGKILL or (done.returncode == 2 and "worker process died" in done.stderr)


def test_report_is_complete_or_absent(checked):
    done, out = checked
    if _grader_killed(done):
        assert not GRADER_OUT_OF_REACH, f"the node killed the grader under {CAP.isolation}"
        assert not (out / "report.json").exists(), "a killed grader left a report that looks complete"
        assert done.returncode == -signal.SIGKILL or (out / "rosgrade-error.txt").is_file(), done.stderr
        return
    assert done.returncode in (0, 1), done.stderr
    report = json.loads((out / "report.json").read_text())
    task = report["tasks"][0]
    if REFUSES:
        assert task["status"] == "error" and "refusing to run the student's code as root" in task["message"]
    else:
        assert task["status"] in ("graded", "timeout"), task
    assert report["isolation"] == CAP.isolation


def test_json_output_holds_only_the_report(checked):
    done, _ = checked
    assert "PWNED" not in done.stdout
    if _grader_killed(done):
        assert done.stdout == ""  # no partial report on stdout either
    else:
        assert json.loads(done.stdout)["isolation"] == CAP.isolation
