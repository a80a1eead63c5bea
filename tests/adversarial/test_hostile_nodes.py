"""Hostile and broken nodes: each ends in a recorded status with a plain message, and nothing of it escapes."""
from __future__ import annotations

import hashlib
import os
import shutil
import sys
import tempfile
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from adversarial_helpers import CORPUS, LIMITS, assert_nothing_escaped, run_case  # noqa: E402

from grader.recording import Recording  # noqa: E402
from grader.runtime import confine  # noqa: E402
from grader.runtime.spec import Limits  # noqa: E402

SANDBOXED = confine.detect().namespaces
needs_sandbox = pytest.mark.skipif(not SANDBOXED, reason="neither bubblewrap nor user namespaces (unshare) are "
                                   "available here: nodes run with " + confine.detect().isolation)


@pytest.fixture(autouse=True)
def _no_leftovers():
    yield
    assert_nothing_escaped()


def _files_under(folder: Path) -> set[Path]:
    return {p for p in folder.rglob("*")}


# -- hangs and loops -----------------------------------------------------------------------------------------------
def test_ignores_sigint_and_sigterm(tmp_path):
    case = run_case("ignore_signals", tmp_path)
    assert case.node.status == "killed_after_shutdown"
    assert "ignored Ctrl+C and SIGTERM" in case.node.message
    assert case.node.exit_signal == 9


@pytest.mark.slow
def test_pure_python_busy_loop(tmp_path):
    case = run_case("busy_loop", tmp_path)
    # The runtime turns a busy loop's CPU time into sim time, so the run reaches Ctrl+C; the loop ignores it.
    assert case.node.status == "killed_after_shutdown"
    assert case.result.wall_s < LIMITS.wall_s


def test_sleep_forever(tmp_path):
    case = run_case("sleep_forever", tmp_path)
    assert case.node.status == "killed_after_shutdown"
    assert case.result.wall_s < 5


@pytest.mark.slow
def test_thread_that_never_ends(tmp_path):
    # Student threads run in sim time now, so the endless thread costs no wall time; as under real rospy (which
    # swallows the KeyboardInterrupt of Ctrl+C), its non-daemon thread keeps the process alive until SIGKILL.
    case = run_case("endless_thread", tmp_path)
    assert case.node.status == "killed_after_shutdown"
    assert case.result.wall_s < 5


@pytest.mark.slow
def test_hang_after_a_good_circle_keeps_the_circle_points(tmp_path):
    from grader.rubric import load_rubrics
    from grader.scoring import score_task

    case = run_case("circle_then_hang", tmp_path, duration=16.0, shutdown_at=14.0)
    assert case.node.status == "timeout"
    assert "did not yield" in case.node.message
    recording = Recording.open(case.folder / "run.mcap")
    odometry = recording.odometry()
    assert odometry.t[-1] > 15.0  # the world kept recording after the node was stopped
    rubric = load_rubrics()["move_circle"]
    report = score_task(rubric, {scenario.name: recording for scenario in rubric.scenarios})
    radius = next(c for c in report.criteria if c.id == "radius")
    assert radius.score == radius.max_score, radius


# -- resource limits -----------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_fork_bomb(tmp_path):
    case = run_case("fork_bomb", tmp_path)
    assert case.node.status == "killed_by_limit"
    assert "limit of 32" in case.node.message and "fork bomb" in case.node.message


def test_memory_hog(tmp_path):
    case = run_case("memory_hog", tmp_path)
    assert case.node.status == "killed_by_limit"
    assert case.node.message == "ran out of memory: the limit is 300 MB (MemoryError)"


def test_output_flood(tmp_path):
    case = run_case("output_flood", tmp_path)
    assert case.node.status == "killed_by_limit"
    assert case.node.message == "printed more than its output limit of 200000 bytes; it was stopped"
    assert (case.folder / "run.log").stat().st_size < 3 * LIMITS.output_bytes


def test_cpu_limit(tmp_path):
    limits = Limits(wall_s=20, silent_wall_s=10, cpu_s=1, memory_mb=300, processes=32, output_bytes=200_000)
    script = tmp_path / "cpu_burner.py"
    script.write_text("import rospy, ctypes\nrospy.init_node('burn')\n"
                      "libc = ctypes.CDLL(None)\nwhile True:\n    libc.getpid()\n")
    case = run_case("cpu_burner", tmp_path, limits=limits, script=script)
    # A busy loop in C is charged as sim time like any other; what stops it here is the 1 s CPU limit.
    assert case.node.status in ("killed_by_limit", "killed_after_shutdown")
    if case.node.status == "killed_by_limit":
        assert "CPU-time limit of 1 s" in case.node.message


def test_file_size_limit(tmp_path):
    limits = Limits(wall_s=20, silent_wall_s=3, memory_mb=300, processes=32, file_mb=1, output_bytes=200_000)
    script = tmp_path / "big_file.py"
    script.write_text("import rospy\nrospy.init_node('big')\nwith open('big.bin', 'wb') as f:\n"
                      "    f.write(b'x' * (4 << 20))\n")
    case = run_case("big_file", tmp_path, limits=limits, script=script)
    assert case.node.status == "killed_by_limit" or "No space left" in case.output or "File too large" in case.output


# -- ending on its own terms ----------------------------------------------------------------------------------------
def test_os_exit(tmp_path):
    case = run_case("os_exit", tmp_path)
    assert (case.node.status, case.node.exit_code, case.node.message) == ("exited", 3, "exited with code 3")
    assert "leaving" in case.output


def test_segfault(tmp_path):
    case = run_case("segfault", tmp_path)
    assert case.node.status == "crashed"
    assert case.node.exit_signal == 11
    assert case.node.message.startswith("crashed with a segmentation fault (SIGSEGV)")


@pytest.mark.skipif(not SANDBOXED and os.geteuid() != 0, reason="with rlimits only the node runs as our user and "
                    "can kill this test process: tests/isolation/test_grader_survives.py checks that mode instead")
def test_kill_parent(tmp_path):
    case = run_case("kill_parent", tmp_path)
    assert case.node.status == "exited"
    assert "still here" in case.output
    if SANDBOXED and os.geteuid() == 0:  # its own uid: no signal reaches root's processes (in a user namespace,
        assert "Operation not permitted" in case.output  # the kernel drops them silently: pid 1 has no handler)


def test_kill_own_process_group(tmp_path):
    case = run_case("kill_group", tmp_path)
    assert case.node.status == "crashed"
    assert "SIGKILL, not by the grader" in case.node.message


def test_daemon_that_leaves_the_session(tmp_path):
    case = run_case("escape_session", tmp_path)
    assert case.node.status in ("exited", "timeout")
    # the autouse fixture checks that the setsid() daemons are gone


def test_deep_recursion(tmp_path):
    case = run_case("deep_recursion", tmp_path)
    assert case.node.status == "exited"
    assert "RecursionError" in case.node.message and "recursion" in case.node.message


def test_missing_module(tmp_path):
    case = run_case("missing_module", tmp_path)
    assert case.node.status == "exited"
    assert "cv2 is not available in the grader (ModuleNotFoundError: No module named 'cv2')" in case.node.message
    assert any(d.startswith("cv2 is not available in the grader: ModuleNotFoundError: No module named 'cv2'")
               for d in case.result.diagnostics)


# -- confinement -----------------------------------------------------------------------------------------------------
@needs_sandbox
def test_writes_outside_its_folder_fail(tmp_path):
    victim = tmp_path / "victim.txt"
    before = _files_under(tmp_path)
    case = run_case("write_outside", tmp_path, args=(str(victim), "/work/pwned", str(Path.cwd() / "pwned"),
                                                     "/dev/rosgrade-pwned"))
    assert case.node.status == "exited"
    # Writes may only land in its private /tmp (as an unprivileged user it owns the folders above its package
    # there); none of them reaches the host, checked below.
    wrote = [line.split("WROTE ", 1)[1] for line in case.output.splitlines() if "WROTE " in line]
    assert all(path.startswith(confine.SANDBOX_HOME + "/") for path in wrote), wrote
    assert "scratch ok" in case.output  # its private folder is writable
    assert not victim.exists() and not Path("/work/pwned").exists() and not (Path.cwd() / "pwned").exists()
    assert not (case.package / "dropped.txt").exists()
    created = {p for p in _files_under(tmp_path) - before if case.folder not in p.parents and p != case.folder}
    assert created <= {case.package, case.package.parent, case.package / "write_outside.py"}, created


@needs_sandbox
def test_reads_of_rubrics_and_other_students_fail(tmp_path):
    other = tmp_path / "other_student" / "move_circle.py"
    other.parent.mkdir()
    other.write_text("SECRET = 'bob'\n")
    rubric = Path(__file__).resolve().parents[2] / "rubrics" / "move_circle.toml"
    case = run_case("read_secrets", tmp_path, args=(str(other), str(rubric), str(case_out := tmp_path / "run")))
    assert case.node.status == "exited"
    assert "READ" not in case.output
    assert f"cannot read {other}" in case.output and f"cannot read {rubric}" in case.output
    assert case_out.exists()


@needs_sandbox
def test_network_is_unreachable(tmp_path):
    case = run_case("network", tmp_path)
    assert case.node.status == "exited"
    assert "CONNECTED" not in case.output
    assert "connect 1.1.1.1:80 failed: OSError: [Errno 101] Network is unreachable" in case.output


@needs_sandbox
def test_runs_as_unprivileged_user(tmp_path):
    script = tmp_path / "whoami.py"
    script.write_text("import os, rospy\nrospy.init_node('who')\nprint('uid', os.getuid(), os.geteuid(), "
                      "'pid', os.getpid(), 'cwd', os.getcwd())\n")
    case = run_case("whoami", tmp_path, script=script)
    assert case.node.status == "exited"
    line = next(line for line in case.output.splitlines() if "uid " in line)
    uid = int(line.split("uid ")[1].split()[0])
    if os.geteuid() == 0:
        assert uid >= confine.UID_BASE
    assert "pid 2 " in line and "cwd /tmp" in line


# -- lying to the grader -----------------------------------------------------------------------------------------------
def test_forged_frames_on_the_channel(tmp_path):
    case = run_case("forge_channel", tmp_path)
    assert case.node.status == "protocol_violation"
    assert case.node.message == "the node broke the grader's channel: unexpected frame kind 250"


def test_monkeypatched_time_and_fake_odometry_do_not_count(tmp_path):
    case = run_case("monkeypatch", tmp_path)
    assert case.node.status in ("exited", "killed_after_shutdown")
    recording = Recording.open(case.folder / "run.mcap")
    odometry = recording.odometry()  # the robot's own odometry (/gazebo), not the node's fake one
    assert abs(odometry.x).max() < 0.01
    assert any("published on /odom, which only the simulated robot" in d for d in case.result.diagnostics)
    assert odometry.t[-1] <= 10.0  # stamps are world time, whatever time.time() says in the node


def test_nan_and_inf_velocities(tmp_path):
    case = run_case("nan_velocity", tmp_path)
    assert case.node.status == "exited"
    recording = Recording.open(case.folder / "run.mcap")
    truth = recording.ground_truth()
    for series in (truth.x, truth.y, truth.yaw):
        assert all(v == v and abs(v) < 1e6 for v in series)  # physics stayed finite


def test_message_storm(tmp_path):
    case = run_case("message_storm", tmp_path)
    assert case.node.status in ("exited", "killed_after_shutdown")
    assert case.result.wall_s < LIMITS.wall_s
    published = next(t for t in case.result.topics if "/cmd_vel" in t and "published" in t)
    # Each publish costs 1 ms of sim time: at most ~1000 per sim second, however fast the loop.
    assert int(published.split(" published ")[1].split()[0]) <= 8 * 1000 + 10


def test_huge_message(tmp_path):
    case = run_case("huge_message", tmp_path)
    assert case.node.status == "protocol_violation"
    assert "frame length" in case.node.message and "8388608" in case.node.message


# -- determinism with confinement on -----------------------------------------------------------------------------------
@pytest.mark.slow
def test_recording_is_bit_identical_run_to_run(tmp_path):
    reference = Path(__file__).resolve().parents[2] / "reference_solutions" / "move_circle.py"
    digests = []
    for _attempt in range(2):
        shutil.rmtree(tmp_path / "run", ignore_errors=True)  # same paths both times: they appear in log records
        case = run_case("move_circle", tmp_path, script=reference, duration=8.0, shutdown_at=6.0)
        assert case.node.status == "exited", case.node.message
        digests.append(hashlib.sha256((case.folder / "run.mcap").read_bytes()).hexdigest())
    assert digests[0] == digests[1]


def test_corpus_is_complete():
    """Every corpus node is run by some adversarial test (by its quoted name), so none is forgotten."""
    tests = "".join(p.read_text("utf-8") for p in Path(__file__).parent.glob("test_*.py"))
    unused = {p.stem for p in CORPUS.glob("*.py") if f'"{p.stem}"' not in tests}
    assert not unused


@pytest.fixture
def readable_tmp():
    """A folder every user can reach (pytest's own is private to its user), removed afterwards."""
    folder = Path(tempfile.mkdtemp(prefix="rosgrade-test-"))
    folder.chmod(0o755)
    yield folder
    shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture
def no_sandbox(monkeypatch):
    """Nodes run with rlimits only (or a per-node uid as root) for one test."""
    monkeypatch.setenv(confine.ENV_DISABLE, "1")
    confine.detect(refresh=True)
    yield
    monkeypatch.delenv(confine.ENV_DISABLE)
    confine.detect(refresh=True)


ROOT_ONLY_PYTHON = os.geteuid() == 0 and not confine.readable_by_others(Path(sys.executable))


@pytest.mark.skipif(ROOT_ONLY_PYTHON, reason="as root with an interpreter only root can read, the fallback refuses "
                    "to run nodes (test_fallback_as_root_never_runs_the_node_as_root)")
def test_fallback_without_sandbox_says_so_and_still_cleans_up(readable_tmp, no_sandbox):
    case = run_case("escape_session", readable_tmp)
    assert any("Node isolation was turned off" in d for d in case.result.diagnostics)
    assert_nothing_escaped()


@pytest.mark.skipif(os.geteuid() != 0, reason="only a grader running as root could run a node as root")
def test_fallback_as_root_never_runs_the_node_as_root(tmp_path, readable_tmp, no_sandbox):
    from grader.runtime.session import RunError, run
    from grader.runtime.spec import NodeSpec, RunSpec
    from sim import Scenario

    script = tmp_path / "whoami.py"
    script.write_text("import os, rospy\nrospy.init_node('who')\nprint('uid', os.getuid())\n")
    if ROOT_ONLY_PYTHON:
        with pytest.raises(RunError, match="refusing to run the student's code as root: .*apt install bubblewrap"):
            run(RunSpec(scenario=Scenario(duration=2.0, shutdown_at=1.0), nodes=(NodeSpec(script=script),)),
                tmp_path / "run.mcap", tmp_path / "run.log")
        return
    case = run_case("whoami", readable_tmp, script=script)
    assert int(case.output.split("uid ")[1].split()[0]) in confine.uid_range(), case.output


@needs_sandbox
def test_package_only_root_may_read_still_runs(tmp_path):
    script = tmp_path / "private.py"
    script.write_text("import rospy\nrospy.init_node('private')\nprint('ran')\n")
    script.chmod(0o600)
    case = run_case("private", tmp_path, script=script)  # copied with its mode: only root may read it
    assert (case.package / "private.py").stat().st_mode & 0o777 == 0o600
    assert case.node.status == "exited" and "ran" in case.output, case.output
    assert not (tmp_path / "run" / "package").exists()
