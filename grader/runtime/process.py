"""Start a student's node as its own process, confined and with rlimits, and make sure nothing of it outlives the run."""
from __future__ import annotations

import contextlib
import functools
import os
import platform
import secrets
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from grader.runtime import confine
from grader.nodelib import COMMON, precompile, pythonpath
from grader.runtime.spec import FILE_ARG, Limits, NodeSpec

try:
    import resource
except ImportError:  # Windows: no rlimits; the grader's own watchdogs still apply
    resource = None  # type: ignore[assignment]

# Every node process (and whatever it starts without clearing its environment) carries this variable, so leftovers
# can be found through /proc even when they left the node's process group. Its value starts with the grader's pid
# (see marker_prefix), so one grader's leftovers are told apart from those of other graders on the same machine.
MARKER_ENV = "ROSGRADE_NODE_MARKER"
ENTRY_LAUNCHER = COMMON / "rosgrade_entry.py"

# Nothing of the grader's environment leaks into the node except what a terminal on a ROS machine would give it;
# ROS_* and PYTHONPATH are dropped so a real ROS install on this machine is never picked up.
_KEPT_ENV = ("PATH", "LANG", "LC_ALL", "TZ", "TERM")
# Python >= 3.12 prints a SyntaxWarning for an invalid escape ("\d", "\777") as it compiles a script; Noetic's Python
# (3.8) says nothing (a hidden DeprecationWarning, as on 3.11), so a rospy node does not print it on any grader's
# Python. An rclpy node keeps it: Jazzy's Python (3.12) prints it.
_ROS1_WARNINGS = "ignore:invalid escape sequence:SyntaxWarning,ignore:invalid octal escape sequence:SyntaxWarning"
# Seconds close() keeps looking for stragglers (a fork bomb refills while it is being killed).
_REAP_S = 5.0


class ProcessError(Exception):
    """A node process could not be started."""


def marker_prefix(grader_pid: int | None = None) -> str:
    """How the marker of every node started by the grader `grader_pid` (default: this process) begins."""
    return f"{grader_pid or os.getpid()}-"


@functools.cache
def _baseline_kernels() -> dict[str, str]:
    """numpy and OpenBLAS pick their kernels for the CPU they run on (AVX-512 arctan2, FMA dot products), so a node's
    numpy gives other last bits on another machine, and its commands and recording follow. Held to their x86-64
    baseline kernels, a node computes the same bits on every x86-64 grader (MuJoCo already needs AVX of it)."""
    if platform.machine() not in ("x86_64", "AMD64"):
        return {}
    import numpy  # the grader's own, which is what the node's interpreter imports

    umath = getattr(getattr(numpy, "_core", None), "_multiarray_umath", None) \
        or numpy.core._multiarray_umath  # numpy 1.x
    return {"NPY_DISABLE_CPU_FEATURES": " ".join(umath.__cpu_dispatch__), "OPENBLAS_CORETYPE": "Sandybridge"}


def node_environment(spec: NodeSpec, channel: str, home: Path | str) -> dict[str, str]:
    env = {k: os.environ[k] for k in _KEPT_ENV if k in os.environ}
    env.update(_baseline_kernels())
    env.update(
        HOME=str(home),
        TMPDIR=str(home),
        PYTHONPATH=os.pathsep.join([pythonpath(spec.flavour), *map(str, spec.import_roots)]),
        PYTHONDONTWRITEBYTECODE="1",
        PYTHONNOUSERSITE="1",
        # Set iteration order (and so anything a node prints from a set) must not vary between runs.
        PYTHONHASHSEED="0",
        PYTHONIOENCODING="utf-8",
        # One BLAS/OpenMP thread: numpy in a node stays within the process limit and gives the same sums every run.
        OPENBLAS_NUM_THREADS="1",
        OMP_NUM_THREADS="1",
        MKL_NUM_THREADS="1",
        ROSGRADE_CHANNEL=channel,
        ROS_MASTER_URI="http://localhost:11311",
    )
    env.setdefault("LANG", "C.UTF-8")
    if spec.flavour == "ros1":
        env["PYTHONWARNINGS"] = _ROS1_WARNINGS
    if spec.ros_namespace:
        env["ROS_NAMESPACE"] = spec.ros_namespace
    return env


def _start_command(spec: NodeSpec, script: Path) -> list[str]:
    """What follows ``python3 -B``: the script, or for an ament_python node the entry-point launcher, as `ros2 run`."""
    entry = spec.entry
    if entry is None:
        return [str(script)]
    return [str(ENTRY_LAUNCHER), str(entry.root), f"{entry.module}:{entry.function}", entry.executable]


def _write_files(spec: NodeSpec, workdir: Path) -> Path | None:
    """Write the files the node is given (NodeSpec.files) into a folder of its work folder, readable by any user."""
    if not spec.files:
        return None
    folder = workdir / "files"
    folder.mkdir(mode=0o755, exist_ok=True)
    os.chmod(folder, 0o755)
    for name, content in spec.files:
        path = folder / name
        path.write_bytes(content)
        os.chmod(path, 0o644)
    return folder


def _with_file_paths(args: tuple[str, ...], files: Path | None) -> list[str]:
    """The node's arguments with each file_arg(name) replaced by where the node sees that file."""
    if files is None:
        return list(args)
    inside = confine.files_folder(files)
    return [f"{inside}/{a[len(FILE_ARG):]}" if a.startswith(FILE_ARG) else a for a in args]


def _own_process_count() -> int:
    """Processes and threads of this user now (RLIMIT_NPROC counts them all, not just the node's)."""
    uid = os.getuid()
    total = 0
    for pid in confine.processes():
        fields = confine.status_fields(pid)
        if fields.get("Uid", "").split()[:1] == [str(uid)]:
            total += int(fields.get("Threads", "1") or 1)
    return total


def rlimit_pairs(limits: Limits, nproc: int | None) -> list[tuple[int, tuple[int, int]]]:
    """The rlimits for a node; nproc None leaves the process count to the grader's watchdogs."""
    if resource is None:
        return []
    cpu = max(1, int(limits.cpu_s))
    pairs = [
        (resource.RLIMIT_CPU, (cpu, cpu + 5)),
        (resource.RLIMIT_AS, (limits.memory_mb << 20, limits.memory_mb << 20)),
        (resource.RLIMIT_FSIZE, (limits.file_mb << 20, limits.file_mb << 20)),
        (resource.RLIMIT_CORE, (0, 0)),
    ]
    if nproc is not None and hasattr(resource, "RLIMIT_NPROC"):
        pairs.append((resource.RLIMIT_NPROC, (nproc, nproc)))
    return pairs


def _child_setup(pairs: list[tuple[int, tuple[int, int]]], uid: int | None) -> None:
    """Runs in the child between fork and exec: rlimits the kernel enforces for us, then (no sandbox) the uid."""
    for which, value in pairs:
        try:
            resource.setrlimit(which, value)
        except (ValueError, OSError):
            pass
    # Ctrl+C from the grader's terminal must not reach the node directly: shutdown is the grader's decision.
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    # A lockstep node never needs the CPU the moment it wakes: SCHED_BATCH stops its wake-ups from preempting the
    # grader (and its threads' hand-overs from preempting each other), which measured 7-27 % less node CPU time.
    with contextlib.suppress(AttributeError, OSError):
        os.sched_setscheduler(0, os.SCHED_BATCH, os.sched_param(0))
    if uid is not None:
        confine.drop_privileges(uid)
    # Dies with the grader (bwrap and unshare pass it on to the whole sandbox). Set after the uid change, which
    # clears it.
    confine.die_with_parent()


@dataclass(frozen=True)
class Usage:
    """Resources all of a node's processes hold together."""

    memory_bytes: int
    cpu_s: float
    tasks: int


class NodeProcess:
    """One running node: its Popen, the grader's ends of the channel pipes, and its raw-output file."""

    # Popen pids of the nodes this grader has open: without namespaces, the grader's other new children are
    # orphans of some node (the grader is their child subreaper, see confine.harden_grader).
    _open: set[int] = set()

    def __init__(self, spec: NodeSpec, workdir: Path, raw_output: Path, limits: Limits) -> None:
        self.limits = limits
        self.marker = marker_prefix() + secrets.token_hex(8)
        precompile()
        self.peak_tasks = 0  # processes + threads seen in the node's sandbox when it was killed
        self.hit_process_limit = False  # whether the node was ever seen unable to start another process or thread
        self._at_process_limit = False  # at the last check
        self._queue_pid: int | None = None  # the node's interpreter, once found (queued_s)
        self._init: tuple[int, int | None] | None = None  # the sandbox's init: (pid, start tick), see _sandbox_init
        workdir.mkdir(parents=True, exist_ok=True)
        script = Path(os.path.abspath(spec.script))
        try:
            files = _write_files(spec, workdir)
            self.plan = confine.plan(["-B", *_start_command(spec, script), *_with_file_paths(spec.args, files)],
                                     script, workdir, limits.file_mb, spec.import_roots, files)
        except confine.ConfineError as exc:
            raise ProcessError(str(exc)) from None
        except OSError as exc:
            raise ProcessError(f"could not prepare the sandbox for {script.name}: {exc}") from None
        self.notes = list(self.plan.notes)
        # RLIMIT_NPROC counts a uid's tasks. Under the grader's own (unprivileged) uid the node's ceiling is what the
        # user's other tasks leave of it, which moves as they come and go: it is checked against that total.
        self._shared_nproc: int | None = None
        if self.plan.uid is not None or (self.plan.sandboxed and os.geteuid() == 0):
            nproc: int | None = limits.processes  # the node's own uid: the count is the node's alone
        elif hasattr(os, "getuid") and sys.platform.startswith("linux") and os.getuid() != 0:
            nproc = self._shared_nproc = _own_process_count() + limits.processes
        else:
            nproc = None
        node_to_grader_r, node_to_grader_w = os.pipe()
        grader_to_node_r, grader_to_node_w = os.pipe()
        env = node_environment(spec, f"{grader_to_node_r},{node_to_grader_w}", self.plan.home)
        env[MARKER_ENV] = self.marker
        pairs = rlimit_pairs(limits, nproc)
        # The grader's children from before this node (a pool's other workers, a test's helper process): never
        # this node's orphans, even when they started in the same clock tick as the node. Orphans are looked for
        # only without a sandbox, so only then is the /proc scan worth making.
        self._children_before = frozenset() if self.plan.sandboxed else frozenset(confine.children_of(os.getpid()))
        self.raw_path = raw_output
        self._raw = open(raw_output, "wb")
        try:
            self.popen = subprocess.Popen(
                self.plan.argv,
                cwd=self.plan.cwd,
                env=env,
                stdin=subprocess.PIPE if spec.stdin is not None else subprocess.DEVNULL,
                stdout=self._raw,
                stderr=subprocess.STDOUT,
                pass_fds=(grader_to_node_r, node_to_grader_w),
                start_new_session=True,
                preexec_fn=(lambda: _child_setup(pairs, None if self.plan.sandboxed else self.plan.uid))
                if resource is not None else None,
            )
        except (OSError, subprocess.SubprocessError) as exc:
            self._raw.close()
            for fd in (node_to_grader_r, node_to_grader_w, grader_to_node_r, grader_to_node_w):
                os.close(fd)
            raise ProcessError(f"could not start {script.name}: {exc}") from None
        NodeProcess._open.add(self.popen.pid)
        self._started = confine.started_at(self.popen.pid) or 0
        os.close(grader_to_node_r)
        os.close(node_to_grader_w)
        self.read_fd = node_to_grader_r
        self.write_fd = grader_to_node_w
        if spec.stdin is not None:
            try:
                self.popen.stdin.write(spec.stdin.encode())
                self.popen.stdin.close()
            except OSError:
                pass  # the node closed stdin or died; its outcome says why

    @property
    def pid(self) -> int:
        return self.popen.pid

    # -- finding the node's processes ----------------------------------------------------------------------------
    def _sandbox_init(self) -> int | None:
        """bwrap's init process (pid 1 of the node's pid namespace), a child of the bwrap we started.

        Found by a pass over /proc once, then only checked: still a child of our bwrap, started at the same tick (so
        not another process given its pid): every limits check (once a wall second) asks several times."""
        if not self._leader_held():
            return None
        if self._init is not None:
            pid, started = self._init
            if confine.parent_of(pid) == self.popen.pid and confine.started_at(pid) == started:
                return pid
        kids = confine.children_of(self.popen.pid)
        self._init = (kids[0], confine.started_at(kids[0])) if kids else None
        return kids[0] if kids else None

    def _node_pid(self) -> int | None:
        """The host pid of the node's interpreter (inside the sandbox it is pid 2)."""
        if not self.plan.sandboxed:
            return self.popen.pid
        init = self._sandbox_init()
        kids = confine.children_of(init) if init else []
        return min(kids) if kids else None

    def leftovers(self) -> list[int]:
        """Every process that belongs to this node and still exists (zombies included), by /proc."""
        found: set[int] = set()
        if self.plan.sandboxed:
            # By namespace only while the sandbox's init is alive, never by a namespace id remembered from earlier:
            # a PID namespace ends with its init, and the kernel gives its id to the next namespace made (another
            # student's node in a batch), whose processes would then be taken for this node's and killed.
            init = self._sandbox_init()
            sandbox_ns = confine.pid_namespace(init) if init else None
            own = confine.pid_namespace(os.getpid())
            in_sandbox = set()
            for pid in confine.processes() if sandbox_ns is not None else ():
                ns = confine.pid_namespace(pid)
                if ns is not None and ns != own and ns == sandbox_ns:
                    in_sandbox.add(pid)
            # Still the same init afterwards: the namespace lived through the whole scan, so its id was not reused.
            if in_sandbox and self._sandbox_init() == init and confine.pid_namespace(init) == sandbox_ns:
                found.update(in_sandbox)
        else:
            found.update(self._orphans())
        marker = f"{MARKER_ENV}={self.marker}".encode()
        tree = confine.descendants(self.popen.pid) if self._leader_held() else set()
        for pid in confine.processes():
            if pid == os.getpid():
                continue
            if (pid in tree and pid != self.popen.pid) or confine.has_marker(pid, marker) \
                    or (self.plan.uid is not None and confine.uid_of(pid) == self.plan.uid):
                found.add(pid)
            elif self._leader_held():
                try:
                    if os.getsid(pid) == self.popen.pid or os.getpgid(pid) == self.popen.pid:
                        found.add(pid)
                except OSError:
                    pass
        if self.popen.returncode is None:
            found.add(self.popen.pid)
        return sorted(found)

    def _orphans(self) -> list[int]:
        """Children of the grader started since this node that are no node: what a node double-forked away."""
        return [pid for pid in confine.children_of(os.getpid())
                if pid not in NodeProcess._open and pid not in self._children_before
                and (confine.started_at(pid) or 0) >= self._started]

    def _reap_orphans(self) -> None:
        for pid in self._orphans():
            try:
                os.waitpid(pid, os.WNOHANG)
            except ChildProcessError:
                pass

    def census(self) -> int:
        """Processes and threads the node has now (bwrap's own two processes not counted)."""
        pids = [p for p in self.leftovers() if p != self.popen.pid]
        if self.plan.sandboxed:
            init = self._sandbox_init()
            pids = [p for p in pids if p != init]
        total = 0
        for pid in pids:
            fields = confine.status_fields(pid)
            if fields.get("State", "").startswith("Z"):
                continue
            total += int(fields.get("Threads", "1") or 1)
        return total

    def _own_processes(self) -> list[int]:
        """The node's live processes, without the sandbox's own (bwrap or unshare, and the pid 1 under it)."""
        skip = {self.popen.pid, self._sandbox_init() if self.plan.sandboxed else None}
        return [p for p in self.leftovers() if p not in skip and not confine.exited(p)]

    def usage(self) -> Usage:
        """What all of the node's processes use together now: memory (with its private /tmp and /dev/shm files),
        CPU seconds, processes and threads."""
        pids = self._own_processes()
        memory = sum(confine.pss_bytes(pid) for pid in pids)
        node = self._node_pid() if self.plan.sandboxed else None
        if node is not None:
            memory += sum(confine.tmpfs_used(f"/proc/{node}/root{folder}") for folder in (confine.SANDBOX_HOME,
                                                                                      "/dev/shm"))
        tasks = sum(int(confine.status_fields(pid).get("Threads", "1") or 1) for pid in pids)
        return Usage(memory, sum(confine.cpu_seconds(pid) for pid in pids), tasks)

    def queued_s(self) -> float:
        """Seconds the node's interpreter has spent runnable but waiting for a CPU (the kernel's schedstat; 0 where
        the kernel keeps none): time a busy machine took from it, not time it chose to spend."""
        if self._queue_pid is None:
            self._queue_pid = self._node_pid()
        try:
            with open(f"/proc/{self._queue_pid}/schedstat", "rb") as stat:
                return int(stat.read().split()[1]) / 1e9
        except (OSError, ValueError, IndexError):
            return 0.0

    def _note_tasks(self, tasks: int) -> bool:
        """Record the node's task count; whether it is at its process limit, where forks fail."""
        self.peak_tasks = max(self.peak_tasks, tasks)
        at_limit = tasks >= self.limits.processes - 1
        # The user-wide count is a /proc scan: made only once the node holds half its budget, which no node that
        # starts a thread or two comes near.
        if not at_limit and self._shared_nproc is not None and tasks >= self.limits.processes // 2:
            at_limit = _own_process_count() >= self._shared_nproc - 1
        self.hit_process_limit = self.hit_process_limit or at_limit
        return at_limit

    def over_limit(self) -> str | None:
        """Why the node as a whole (every process it started) is over its limits, or None."""
        usage = self.usage()
        at_limit, was_at_limit = self._note_tasks(usage.tasks), self._at_process_limit
        self._at_process_limit = at_limit
        if usage.memory_bytes > self.limits.memory_mb << 20:
            why = (f"its processes together used more than its memory limit of {self.limits.memory_mb} MB "
                   f"({usage.memory_bytes >> 20} MB, files in its /tmp and /dev/shm included); it was stopped")
        elif usage.cpu_s > self.limits.cpu_s + 1:
            why = (f"its processes together used more than its CPU-time limit of {self.limits.cpu_s:g} s; "
                   "it was stopped")
        else:
            why = None
        # A node held at its process limit spends its CPU and memory on forking: that is the cause to name, whichever
        # of the totals tripped first (the rlimit keeps the count itself from going far past the limit).
        # Held at the limit for two checks in a row (a second apart) is a fork bomb whatever else it does: its forks
        # load the machine, so waiting for its silence to run out would name the silence.
        if usage.tasks > self.limits.processes or (at_limit and (why or was_at_limit)):
            return (f"started {usage.tasks} processes and threads, at or over its limit of {self.limits.processes} "
                    "(a fork bomb or runaway threads?); it was stopped and everything it started killed")
        return why

    # -- signalling ---------------------------------------------------------------------------------------------
    def signal_group(self, sig: int) -> None:
        """Signal the node and everything it started. SIGKILL reaches all of it, wherever it went."""
        if sig == signal.SIGKILL:
            self._note_tasks(self.census())
            self._kill_all()
            return
        target = self._node_pid()
        if target is None or (target == self.popen.pid and not self._leader_held()):
            return  # the node has exited and been reaped: its pid may be another process's by now
        try:
            os.killpg(target, sig)
        except (ProcessLookupError, PermissionError):
            try:
                os.kill(target, sig)
            except (ProcessLookupError, PermissionError, OSError):
                pass

    def _leader_held(self) -> bool:
        """Whether the process we started is not reaped yet, so that its pid (and the process group named after it)
        is still ours: once reaped, the kernel may give that number to another grader's new node."""
        return self.popen.returncode is None

    def _kill_all(self) -> None:
        deadline = time.monotonic() + _REAP_S
        while True:
            if self._leader_held():
                try:
                    os.killpg(self.popen.pid, signal.SIGKILL)
                except (ProcessLookupError, PermissionError):
                    pass
            left = [p for p in self.leftovers() if not confine.exited(p)]
            for pid in left:
                try:
                    os.kill(pid, signal.SIGKILL)
                except (ProcessLookupError, PermissionError):
                    pass
            if not self.plan.sandboxed:
                self._reap_orphans()
            if not left or time.monotonic() > deadline:
                return
            time.sleep(0.01)

    def wait(self, timeout: float | None = None) -> int | None:
        """The node's exit code (negative: the signal that killed it), or None if it is still running."""
        try:
            code = self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            return None
        # bwrap reports a child killed by signal n as exit code 128 + n.
        if self.plan.sandboxed and 128 < code < 128 + 65:
            return -(code - 128)
        return code

    @property
    def returncode(self) -> int | None:
        """Like wait(0) without waiting: the exit code once the node has been reaped."""
        code = self.popen.returncode
        if code is not None and self.plan.sandboxed and 128 < code < 128 + 65:
            return -(code - 128)
        return code

    def close(self) -> None:
        """Kill whatever is left of the node and release every descriptor."""
        self.signal_group(signal.SIGKILL)
        self.wait(5.0)
        NodeProcess._open.discard(self.popen.pid)
        for fd in (self.read_fd, self.write_fd):
            try:
                os.close(fd)
            except OSError:
                pass
        self._raw.close()
        if self.plan.uid is not None and not self.plan.sandboxed:
            confine.remove_files_of(self.plan.uid)
        if self.plan.staged is not None:
            shutil.rmtree(self.plan.staged, ignore_errors=True)
