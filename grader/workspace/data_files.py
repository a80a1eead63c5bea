"""setup.py's ``data_files`` read as data: which of an ament_python package's files `colcon build` installs where.

The forms the ROS 2 tutorials and course packages write are understood: string lists, ``glob(...)`` of a pattern
(``os.path.join`` pieces, ``'share/' + package_name``, f-strings), and lists added together. A value that cannot be
read without running setup.py makes the whole list unknown (None), and the caller then assumes what a package
usually installs rather than refusing a file the build may well install.
"""
from __future__ import annotations

import ast
import glob
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

MAX_MATCHES = 2000  # files one glob may install; a package has a few launch and config files

Text = Callable[[ast.AST], "str | None"]


class _Unreadable(Exception):
    """A data_files value that cannot be known without running setup.py."""


@dataclass(frozen=True)
class DataFiles:
    """One ``(destination, sources)`` entry: sources are file paths or glob patterns relative to the package."""

    destination: str
    sources: tuple[str, ...]
    kinds: tuple[str, ...]  # per source: "file" (named outright), "glob", or "rglob" (glob(..., recursive=True))


def _joined(node: ast.AST, text: Text) -> str | None:
    """``os.path.join('share', package_name, 'launch')`` (or ``path.join``/``join``) as one text."""
    if not isinstance(node, ast.Call) or node.keywords:
        return None
    name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
    if name != "join":
        return None
    parts = [_text(arg, text) for arg in node.args]
    return "/".join(parts) if parts and all(p is not None for p in parts) else None  # type: ignore[arg-type]


def _text(node: ast.AST, text: Text) -> str | None:
    """A text setup.py's constants give, or an os.path.join of such texts."""
    value = text(node)
    return value if value is not None else _joined(node, text)


def _sources(node: ast.AST, text: Text) -> list[tuple[str, str]]:
    """The files (or glob patterns) one sources expression names, with their kind; _Unreadable if it cannot be
    known."""
    if isinstance(node, (ast.List, ast.Tuple)):
        found = [(_text(item, text), "file") for item in node.elts]
        if any(name is None for name, _ in found):
            raise _Unreadable
        return found  # type: ignore[return-value]
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        return _sources(node.left, text) + _sources(node.right, text)
    if isinstance(node, ast.Call) and getattr(node.func, "id", getattr(node.func, "attr", "")) == "glob" \
            and len(node.args) == 1 and all(k.arg == "recursive" for k in node.keywords):
        pattern = _text(node.args[0], text)
        flags = [k.value.value if isinstance(k.value, ast.Constant) else None for k in node.keywords]
        if pattern is None or any(not isinstance(flag, bool) for flag in flags):
            raise _Unreadable
        return [(pattern, "rglob" if any(flags) else "glob")]
    raise _Unreadable


def read_data_files(tree: ast.Module, text: Text) -> tuple[DataFiles, ...] | None:
    """The ``data_files=[...]`` of setup.py's call, () when it gives none, None when it cannot be read as data."""
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        for keyword in node.keywords:
            if keyword.arg != "data_files":
                continue
            if not isinstance(keyword.value, (ast.List, ast.Tuple)):
                return None
            entries = []
            for item in keyword.value.elts:
                if not isinstance(item, ast.Tuple) or len(item.elts) != 2:
                    return None
                destination = _text(item.elts[0], text)
                try:
                    sources = _sources(item.elts[1], text)
                except _Unreadable:
                    return None
                if destination is None:
                    return None
                entries.append(DataFiles(destination, tuple(s for s, _ in sources), tuple(k for _, k in sources)))
            return tuple(entries)
    return ()


def _matches(folder: Path, pattern: str, recursive: bool) -> list[Path]:
    """What ``glob(pattern)`` returns with setup.py's folder as the working directory (as colcon runs it)."""
    if PurePosixPath(pattern).is_absolute() or ".." in PurePosixPath(pattern).parts:
        return []
    found = glob.glob(pattern, root_dir=folder, recursive=recursive)
    return [folder / name for name in sorted(found)[:MAX_MATCHES]]


def installed_share(folder: Path, package: str, entries: tuple[DataFiles, ...]) -> tuple[Path, ...]:
    """The package's files that data_files installs under share/<package> (at any depth), as paths in the package."""
    installed: list[Path] = []
    for entry in entries:
        destination = PurePosixPath(entry.destination.strip("/"))
        if destination.parts[:2] != ("share", package):
            continue
        for source, kind in zip(entry.sources, entry.kinds):
            paths = [folder / source] if kind == "file" else _matches(folder, source, kind == "rglob")
            installed += [path for path in paths if path.is_file()]
    return tuple(dict.fromkeys(installed))
