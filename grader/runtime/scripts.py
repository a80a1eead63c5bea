"""Find a node's script in a submission the way rosrun would, and report what would stop rosrun from running it.

The node still runs through ``python3 script.py`` whatever these checks find: they are findings with a hint, so a
student learns why `rosrun` would fail on the lab machine, not a reason to give zero.
"""
from __future__ import annotations

import os
import stat
from pathlib import Path

from grader.workspace.python_source import compile_quietly

SKIPPED_DIRS = {"build", "devel", "install", "log", "logs", "__pycache__", "node_modules", "__MACOSX"}
# Far above any node a course asks for; compiling more would let a submission spend the grader's time and memory.
MAX_SCRIPT_BYTES = 1024 * 1024


class ScriptNotFound(Exception):
    """No file with the script's name exists in the submission."""


def candidates(root: Path, name: str) -> list[Path]:
    """Every file called `name` under root, skipping build output and hidden folders, best guess first."""
    if root.is_file():
        return [root] if root.name == name else []
    found = []
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in SKIPPED_DIRS)
        if name in files:
            found.append(Path(folder) / name)
    # rosrun looks inside packages; scripts/ and src/ are where the course puts nodes.
    return sorted(found, key=lambda p: (p.parent.name not in ("scripts", "src", "nodes"), len(p.parts), str(p)))


def find_script(root: Path, name: str) -> tuple[Path, list[str]]:
    """The script to run and findings about the choice (e.g. several copies)."""
    found = candidates(root, name)
    if not found:
        raise ScriptNotFound(f"no file named {name} in {root}")
    notes = []
    if len(found) > 1:
        others = ", ".join(str(p.relative_to(root)) for p in found[1:4])
        notes.append(f"Several files are named {name}; graded {found[0].relative_to(root)} (also found: {others}).")
    return found[0], notes


def read_script(path: Path) -> bytes | str:
    """The script's bytes, or why they cannot be read safely: only a regular file, at most MAX_SCRIPT_BYTES.

    Opened without blocking and checked again once open, so a FIFO or device (also one swapped in after the first
    check) is never read: reading a regular file cannot hang, and the size cap bounds it.
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        return f"{path.name} cannot be read ({exc.strerror}); submit it as a plain file."
    with os.fdopen(fd, "rb") as handle:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            return f"{path.name} is not a regular file (a pipe, device or folder); submit the script as a plain file."
        if info.st_size > MAX_SCRIPT_BYTES:
            return f"{path.name} is too large ({info.st_size >> 10} KiB, limit {MAX_SCRIPT_BYTES >> 10} KiB) to be a node."
        raw = handle.read(MAX_SCRIPT_BYTES + 1)
    if len(raw) > MAX_SCRIPT_BYTES:
        return f"{path.name} is too large (it grew past {MAX_SCRIPT_BYTES >> 10} KiB while being read) to be a node."
    return raw


def check_script(path: Path, rosrun: bool = True) -> list[str]:
    """What `rosrun pkg script.py` on a ROS machine would trip over, each with the fix; with ``rosrun`` False
    (a ROS 2 node, started by `ros2 run` or `python3`) only what would stop Python itself."""
    raw = read_script(path)
    if isinstance(raw, str):
        return [raw]
    notes = _rosrun_notes(path, raw) if rosrun else []
    try:
        source = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        notes.append(f"{path.name} is not valid UTF-8 (byte {exc.start}): Python 3 cannot read it. "
                     "Save it as UTF-8.")
        return notes
    if "\0" in source:
        line = source.count("\n", 0, source.index("\0")) + 1
        notes.append(f"{path.name} line {line} contains a NUL byte: Python refuses to run the file. Remove it "
                     "(it often comes from copying code out of a PDF or a binary editor).")
        return notes
    try:
        compile_quietly(source, str(path))
    except SyntaxError as exc:
        hint = " This looks like Python 2 code; ROS Noetic runs Python 3." if _looks_like_python2(source) else ""
        notes.append(f"{path.name} line {exc.lineno}: SyntaxError: {exc.msg}.{hint}")
    except (ValueError, RecursionError, MemoryError) as exc:  # e.g. nesting too deep for the compiler
        notes.append(f"{path.name} cannot be compiled by Python ({type(exc).__name__}); simplify the code.")
    return notes


def _rosrun_notes(path: Path, raw: bytes) -> list[str]:
    """rosrun executes the file itself: it needs a python3 shebang, LF line endings and the execute bit."""
    notes: list[str] = []
    first_line = raw.split(b"\n", 1)[0]
    if not first_line.startswith(b"#!"):
        notes.append(f"{path.name} has no shebang line: rosrun would fail with 'Exec format error'. "
                     "Make `#!/usr/bin/env python3` the very first line.")
    else:
        if first_line.endswith(b"\r"):
            notes.append(f"{path.name} has Windows (CRLF) line endings: rosrun would fail with "
                         "\"/usr/bin/env: 'python3\\r': No such file or directory\". Save it with LF line endings.")
        interpreter = first_line[2:].strip().split()
        if interpreter and interpreter[-1] == b"python":
            notes.append(f"{path.name} asks for `python` in its shebang; ROS Noetic needs `#!/usr/bin/env python3` "
                         "(plain `python` is missing or Python 2 on most lab machines).")
    if not path.stat().st_mode & (stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH):
        notes.append(f"{path.name} is not executable: rosrun would say it can't find an executable named "
                     f"{path.name}. Run `chmod +x {path.name}`.")
    return notes


def _looks_like_python2(source: str) -> bool:
    lines = [line.strip() for line in source.splitlines()]
    return any(line.startswith(("print ", "print\t", "exec ")) and not line.startswith("print(") for line in lines) \
        or "except Exception, " in source or "raw_input(" in source
