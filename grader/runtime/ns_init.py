"""Pid 1 of a node's own namespaces when bubblewrap is missing: hide and protect the host's files, start the node.

`unshare` (util-linux) creates the PID, mount, network, IPC and UTS namespaces (and a user namespace when the grader
is not root) and runs this file as their first process, with `python -I -S`, so it imports nothing but the standard
library and nothing of the student's runs before the node is confined. It then

- makes every file system read-only, covers /tmp with the node's own small tmpfs (its HOME and cwd) and /dev/shm
  with a smaller one, and covers the folders where graders and other students keep files (/home, /root, ...) with
  empty read-only tmpfs, binding back only what the node needs (the interpreter, the client library, its package);
- forks the node as pid 2 in a new session, without root: as its own uid when the grader is root, else in a nested
  user namespace (its real uid, no capabilities), so it can neither undo these mounts nor reach this process;
- reaps every orphan and exits with the node's status (128 + n when a signal n killed it, as bubblewrap does); when
  it exits, the kernel kills whatever is left in the PID namespace.

Usage: python -I -S ns_init.py CONFIG_JSON -- NODE_ARGV...
"""
from __future__ import annotations

import ctypes
import json
import os
import signal
import stat
import sys

MS_RDONLY, MS_NOSUID, MS_NODEV, MS_NOEXEC = 1, 2, 4, 8
MS_REMOUNT, MS_NOATIME, MS_NODIRATIME, MS_BIND, MS_REC = 32, 1024, 2048, 4096, 16384
MS_RELATIME, MS_STRICTATIME = 1 << 21, 1 << 24
_OPTION_FLAGS = {"nosuid": MS_NOSUID, "nodev": MS_NODEV, "noexec": MS_NOEXEC, "noatime": MS_NOATIME,
                 "nodiratime": MS_NODIRATIME, "relatime": MS_RELATIME, "strictatime": MS_STRICTATIME}
CLONE_NEWUSER = 0x10000000
PR_SET_DUMPABLE, PR_SET_NO_NEW_PRIVS = 4, 38
_IGNORED = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
# Exit codes the grader recognises as "the sandbox could not be set up" (the node never ran).
SETUP_FAILED = 125
DROP_FAILED = 126

_libc = ctypes.CDLL(None, use_errno=True)


class SetupError(Exception):
    """A step of the confinement failed; the node must not run."""


def _check(result: int, what: str) -> None:
    if result != 0:
        raise SetupError(f"{what}: {os.strerror(ctypes.get_errno())}")


def _mount(source: str | None, target: str, fstype: str | None, flags: int, data: str | None = None) -> None:
    enc = (lambda s: None if s is None else s.encode())
    _check(_libc.mount(enc(source), enc(target), enc(fstype), ctypes.c_ulong(flags), enc(data)),
           f"mount {target}")


def _unescape(field: str) -> str:
    """Mount points in mountinfo escape space, tab, newline and backslash as octal."""
    out, i = [], 0
    while i < len(field):
        if field[i] == "\\" and len(field[i + 1:i + 4]) == 3 and field[i + 1:i + 4].isdigit():
            out.append(chr(int(field[i + 1:i + 4], 8)))
            i += 4
        else:
            out.append(field[i])
            i += 1
    return "".join(out)


def _mounts() -> list[tuple[str, int, bool]]:
    """(mount point, flags to keep on a remount, read-only already) for every mount this namespace has."""
    found = []
    with open("/proc/self/mountinfo", encoding="utf-8", errors="replace") as handle:
        for line in handle:
            fields = line.split()
            options = fields[5].split(",")
            keep = 0
            for option in options:
                keep |= _OPTION_FLAGS.get(option, 0)
            found.append((_unescape(fields[4]), keep, "ro" in options))
    return found


def read_only_everywhere() -> None:
    """Remount every mount read-only (keeping the flags a user namespace may not drop); /proc stays as it is."""
    for point, keep, read_only in _mounts():
        if read_only or point == "/proc" or point.startswith("/proc/"):
            continue
        try:
            _mount(None, point, None, MS_BIND | MS_REMOUNT | MS_RDONLY | keep)
        except SetupError:
            if point == "/":
                raise
            # A mount we cannot remount (e.g. one the kernel locked) is covered below when it matters; others stay.


def _tmpfs(target: str, size: int, mode: int, read_only: bool = False) -> None:
    _mount("tmpfs", target, "tmpfs", MS_NOSUID | MS_NODEV, f"size={size},mode={mode:o}")
    if read_only:
        os.chmod(target, mode)
        _mount(None, target, None, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV)


def _blocking_parent(path: str, uid: int | None) -> str | None:
    """The highest folder above path the node's uid could not search (only matters when it is not the owner)."""
    if uid is None:
        return None
    parts = path.strip("/").split("/")[:-1]
    for depth in range(1, len(parts) + 1):
        folder = "/" + "/".join(parts[:depth])
        if not os.stat(folder).st_mode & stat.S_IXOTH:
            return folder
    return None


def confine_files(config: dict) -> None:
    """Read-only host, private /tmp and /dev/shm, covered private folders, and the node's own files bound back."""
    uid = config.get("uid")
    # Look at what is shown before anything is covered: covering /root or /tmp hides the originals.
    shown = [(os.open(source, os.O_PATH | os.O_CLOEXEC), target) for source, target in config["show"]]
    blocked = {b for b in (_blocking_parent(target, uid) for _fd, target in shown) if b}
    read_only_everywhere()
    _tmpfs("/tmp", config["tmp_bytes"], 0o1777)
    if os.path.isdir("/dev/shm"):
        _tmpfs("/dev/shm", config["shm_bytes"], 0o1777)
    covers: list[str] = []
    for folder in sorted({*config["cover"], *blocked}):
        inside = any(folder == c or folder.startswith(c + "/") for c in ["/tmp", *covers])
        if not inside and os.path.isdir(folder) and not os.path.islink(folder):
            _tmpfs(folder, 1 << 20, 0o755)
            covers.append(folder)
    os.umask(0o022)
    for fd, target in sorted(shown, key=lambda item: item[1]):
        if stat.S_ISDIR(os.fstat(fd).st_mode):
            os.makedirs(target, mode=0o755, exist_ok=True)
        elif not os.path.exists(target):
            os.makedirs(os.path.dirname(target), mode=0o755, exist_ok=True)
            os.close(os.open(target, os.O_CREAT | os.O_WRONLY, 0o644))
        _mount(f"/proc/self/fd/{fd}", target, None, MS_BIND | MS_REC)
        _mount(None, target, None, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV)
        os.close(fd)
    for folder in covers:
        _mount(None, folder, None, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV)


def _drop_to_uid(uid: int) -> None:
    os.setgroups([])
    os.setgid(uid)
    os.setuid(uid)
    if os.getuid() != uid or os.geteuid() != uid or os.getegid() != uid:
        os._exit(DROP_FAILED)


def _drop_capabilities(outer_uid: int, outer_gid: int) -> None:
    """In a nested user namespace the node has its real uid back and, once it execs, no capability over ours."""
    _check(_libc.unshare(CLONE_NEWUSER), "unshare(CLONE_NEWUSER)")
    with open("/proc/self/setgroups", "w") as handle:
        handle.write("deny")
    with open("/proc/self/uid_map", "w") as handle:
        handle.write(f"{outer_uid} 0 1")
    with open("/proc/self/gid_map", "w") as handle:
        handle.write(f"{outer_gid} 0 1")
    if os.getuid() == 0:
        os._exit(DROP_FAILED)


def _start_node(config: dict, argv: list[str]) -> int:
    pid = os.fork()
    if pid:
        return pid
    try:
        # As a process started by subprocess would: default dispositions (Python ignores SIGPIPE and SIGXFSZ).
        for sig in (*_IGNORED, signal.SIGPIPE, signal.SIGXFSZ):
            signal.signal(sig, signal.SIG_DFL)
        os.setsid()
        _libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
        if config.get("uid") is not None:
            _drop_to_uid(config["uid"])
        else:
            _drop_capabilities(config["outer_uid"], config["outer_gid"])
        os.chdir(config["cwd"])
        os.execv(argv[0], argv)
    except BaseException as exc:  # noqa: BLE001 - the child must never return into the init loop
        os.write(2, f"rosgrade: could not start the node: {exc}\n".encode())
    os._exit(SETUP_FAILED)


def _reap_until(node: int) -> int:
    """Reap every child (orphans are re-parented to us) until the node itself ends; its status as an exit code."""
    while True:
        try:
            pid, status = os.waitpid(-1, 0)
        except ChildProcessError:
            return SETUP_FAILED
        except InterruptedError:
            continue
        if pid == node:
            return 128 + os.WTERMSIG(status) if os.WIFSIGNALED(status) else os.WEXITSTATUS(status)


def main(argv: list[str]) -> int:
    if len(argv) < 4 or argv[2] != "--":
        sys.stderr.write("usage: ns_init.py CONFIG_JSON -- NODE_ARGV...\n")
        return SETUP_FAILED
    config = json.loads(argv[1])  # unshare --kill-child kills us when it ends (and so the whole namespace)
    # Nothing in the namespace may ptrace this process or read its /proc files (it holds capabilities over them).
    _libc.prctl(PR_SET_DUMPABLE, 0, 0, 0, 0)
    for sig in _IGNORED:
        signal.signal(sig, signal.SIG_IGN)  # the grader stops the node itself; pid 1 goes last
    try:
        confine_files(config)
    except (SetupError, OSError) as exc:
        sys.stderr.write(f"rosgrade: could not confine the node: {exc}\n")
        return SETUP_FAILED
    os.chdir("/")
    node = _start_node(config, argv[3:])
    os.closerange(3, os.sysconf("SC_OPEN_MAX"))  # only the node keeps the grader's channel
    return _reap_until(node)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
