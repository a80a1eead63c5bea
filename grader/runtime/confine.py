"""Confine a node process: bubblewrap (no network, private /tmp, read-only system) and an unprivileged uid when we can.

One decision per grader process (`detect()`), made with a real probe, so a machine where bwrap is installed but
cannot work (a container without user namespaces) falls back instead of failing every run. `plan()` turns one node's
command into what `subprocess.Popen` runs. The rlimits are applied by the caller either way (they are inherited
through bwrap). Where nothing stronger is available the plan says so in one plain note.
"""
from __future__ import annotations

import os
import shutil
import stat
import subprocess
import sys
import threading
from dataclasses import dataclass, field
from pathlib import Path

# Where the node's private, writable folder is mounted inside the sandbox; also its HOME, TMPDIR and cwd.
SANDBOX_HOME = "/tmp"
HOSTNAME = "rosgrade"
# Unprivileged uids for nodes: one per node (derived from the grader's pid), so that the kernel's per-user process
# limit counts only that node's processes, and nodes running side by side cannot signal each other.
UID_BASE = 200_000
_UID_SLOTS = 16
# Files of /etc a Python process and its shared libraries read; nothing else of /etc is visible.
_ETC_FILES = ("ld.so.cache", "ld.so.conf", "ld.so.conf.d", "localtime", "nsswitch.conf", "passwd", "group",
              "hosts", "os-release", "alternatives")
_SYSTEM_DIRS = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32")
# Set by the wrapper below: a node that gets here as root must not run.
_DROP_FAILED_EXIT = 126
ENV_DISABLE = "ROSGRADE_NO_SANDBOX"  # "1": run nodes with rlimits only (debugging the grader)

# Runs inside bwrap as root: setgid/setuid to the node's uid and exec the node.
# It runs with -I -S (no site, no environment-driven imports), so nothing of the student's can run before the drop.
_WRAPPER = (
    "import os,sys\n"
    "u=int(sys.argv[1])\n"
    "os.setgroups([]);os.setgid(u);os.setuid(u)\n"
    "if os.getuid()!=u or os.geteuid()!=u or os.getegid()!=u:os._exit(%d)\n"
    "os.execv(sys.argv[2],sys.argv[2:])\n" % _DROP_FAILED_EXIT
)


class ConfineError(Exception):
    """The sandbox could not be set up for a node."""


@dataclass(frozen=True)
class Capability:
    """What this machine lets the grader do to confine nodes (decided once per process)."""

    bwrap: str | None          # path of a working bwrap, or None
    root: bool                 # the grader runs as root: nodes get their own unprivileged uid
    note: str | None = None    # said once per run when confinement is weaker than the full sandbox

    @property
    def mode(self) -> str:
        if self.bwrap:
            return "bwrap"
        return "uid" if self.root and _is_linux() else "rlimits"


@dataclass
class Plan:
    """How to start one node: the command, its cwd and HOME as the node sees them, and who it runs as."""

    argv: list[str]
    cwd: str
    home: str
    uid: int | None = None
    sandboxed: bool = False
    notes: list[str] = field(default_factory=list)
    staged: Path | None = None  # a readable copy of the student's package, removed when the node is closed


_lock = threading.Lock()
_capability: Capability | None = None
_uid_counter = 0


def _is_linux() -> bool:
    return sys.platform.startswith("linux")


def _probe_bwrap(bwrap: str, root: bool) -> str | None:
    """None if a minimal sandbox like the nodes' one starts and runs Python; else why not."""
    argv = [bwrap, *base_args(root), *system_binds(), "--", sys.executable, "-I", "-S", "-c",
            "import socket,os;s=socket.socket();print(os.getpid())"]
    try:
        done = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, timeout=20, check=False)
    except (OSError, subprocess.SubprocessError) as exc:
        return str(exc)
    if done.returncode != 0:
        return (done.stderr.decode("utf-8", "replace").strip().splitlines() or [f"exit code {done.returncode}"])[-1]
    return None


def detect(refresh: bool = False) -> Capability:
    """Find out (once) whether nodes can be sandboxed with bubblewrap on this machine."""
    global _capability
    with _lock:
        if _capability is not None and not refresh:
            return _capability
        root = hasattr(os, "geteuid") and os.geteuid() == 0
        if not _is_linux():
            cap = Capability(None, False, f"Node isolation is not available on {sys.platform}: the node ran with "
                                          "time and output limits only (no network or file isolation).")
        elif os.environ.get(ENV_DISABLE) == "1":
            cap = Capability(None, root, f"Node isolation was turned off ({ENV_DISABLE}=1): the node ran with "
                                         "resource limits only (no network or file isolation).")
        else:
            bwrap = shutil.which("bwrap")
            why = "bubblewrap (bwrap) is not installed" if bwrap is None else _probe_bwrap(bwrap, root)
            if why is None:
                cap = Capability(bwrap, root)
            else:
                cap = Capability(None, root, f"Node isolation is not available here ({why}): the node ran with "
                                             "resource limits only (no network or file isolation)"
                                             + (", as an unprivileged user." if root else "."))
        _capability = cap
        return cap


def next_uid() -> int:
    """A uid no other node of any grader running on this machine has now."""
    global _uid_counter
    with _lock:
        _uid_counter += 1
        return UID_BASE + os.getpid() * _UID_SLOTS + _uid_counter % _UID_SLOTS


def base_args(root: bool) -> list[str]:
    """The namespace and process options of every sandbox."""
    args = ["--die-with-parent", "--new-session", "--unshare-pid", "--unshare-net", "--unshare-ipc",
            "--unshare-uts", "--unshare-cgroup-try", "--hostname", HOSTNAME]
    if not root:
        args.append("--unshare-user")
    return args + ["--proc", "/proc", "--dev", "/dev"]


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


def system_binds() -> list[str]:
    """The interpreter, its standard library and site-packages, shared libraries: read-only."""
    args: list[str] = []
    for path in _SYSTEM_DIRS:
        _bind_path(args, path)
    for name in _ETC_FILES:
        _bind_path(args, f"/etc/{name}")
    prefixes = []
    for path in (sys.base_prefix, sys.prefix, os.path.dirname(os.path.realpath(sys.executable)),
                 os.path.dirname(sys.executable)):
        real = os.path.realpath(path)
        if not any(real == p or real.startswith(p + "/") for p in ("/usr", *prefixes)):
            prefixes.append(real)
    for path in sorted(set(prefixes)):
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
    shutil.copytree(folder, target, symlinks=True)
    for root, dirs, files in os.walk(target):
        os.chmod(root, 0o755)
        for name in files:
            path = os.path.join(root, name)
            if not os.path.islink(path):
                os.chmod(path, os.stat(path).st_mode | 0o444)
    return target


def plan(command: list[str], script: Path, workdir: Path, limits_file_mb: int) -> Plan:
    """How to start `command` (an interpreter running `script`) confined; workdir is the node's host folder."""
    cap = detect()
    notes = [cap.note] if cap.note else []
    if cap.bwrap:
        package, staged = package_folder(script), None
        args = [cap.bwrap, *base_args(cap.root), "--size", str(max(1, limits_file_mb) << 20), "--perms", "1777",
                "--tmpfs", SANDBOX_HOME, *system_binds()]
        nodelib = str(Path(__file__).resolve().parents[1] / "nodelib")
        _ro_bind(args, nodelib)
        if not (str(package) + "/").startswith(nodelib + "/"):
            # Root drops to an unprivileged uid inside: files only root may read are shown through a readable copy.
            staged = None if not cap.root or tree_readable(package) else readable_copy(package, workdir)
            _ro_bind(args, str(staged or package), str(package))
        args += ["--chdir", SANDBOX_HOME]
        uid = None
        if cap.root:
            uid = next_uid()
            args += ["--", sys.executable, "-I", "-S", "-c", _WRAPPER, str(uid), *command]
        else:
            args += ["--", *command]
        return Plan(args, cwd=str(workdir), home=SANDBOX_HOME, uid=uid, sandboxed=True, notes=notes, staged=staged)
    if cap.root and _is_linux():
        unreadable = [p for p in (script, Path(sys.executable), Path(__file__).resolve().parents[1] / "nodelib")
                      if not readable_by_others(p)]
        if not unreadable:
            uid = next_uid()
            os.chown(workdir, uid, uid)
            return Plan(list(command), cwd=str(workdir), home=str(workdir), uid=uid, notes=notes)
        notes.append(f"The node ran as root: {unreadable[0]} is not readable by an unprivileged user.")
    return Plan(list(command), cwd=str(workdir), home=str(workdir), notes=notes)


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


def parent_of(pid: int) -> int | None:
    """The parent pid, from /proc/<pid>/stat (the name field may hold spaces and parentheses)."""
    data = _read(f"/proc/{pid}/stat")
    try:
        return int(data[data.rindex(b")") + 2:].split()[1])
    except (ValueError, IndexError):
        return None


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
