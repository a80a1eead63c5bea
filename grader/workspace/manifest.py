"""Read a package's package.xml and setup.py as data: name, build type, dependencies, entry points, Python packages.

package.xml is parsed with expat (no DTDs or entities expanded) and setup.py as a syntax tree; neither is run.
Both are size-bounded; what cannot be read raises ManifestError with the line a student can fix.
"""
from __future__ import annotations

import ast
import errno
import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path
from xml.parsers import expat

from grader.workspace.data_files import DataFiles, read_data_files
from grader.workspace.python_source import parse

MAX_BYTES = 256 * 1024  # a package.xml or setup.py is a few kB
_NAME = re.compile(rb"<name>\s*([^<\s]+)\s*</name>")
_DEPENDS = {"depend", "build_depend", "exec_depend", "run_depend", "buildtool_depend", "build_export_depend"}
_SYNTAX_ERRORS = (SyntaxError, ValueError, RecursionError, MemoryError)


class ManifestError(Exception):
    """A package.xml or setup.py that cannot be read, or that its tools would refuse."""


def read_regular(path: Path, limit: int) -> bytes:
    """At most ``limit`` bytes of a regular file: opened without blocking and checked once open, so a FIFO or device
    named package.xml or CMakeLists.txt is never read (OSError for those, as for a missing file)."""
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    with os.fdopen(fd, "rb") as handle:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise OSError(errno.EINVAL, "not a regular file")
        return handle.read(limit)


def read_bounded(path: Path) -> bytes:
    """The file's bytes, at most MAX_BYTES (ManifestError if unreadable or larger)."""
    try:
        raw = read_regular(path, MAX_BYTES + 1)
    except OSError as exc:
        raise ManifestError(f"{path.name} cannot be read ({exc.strerror}).") from None
    if len(raw) > MAX_BYTES:
        raise ManifestError(f"{path.name} is larger than {MAX_BYTES >> 10} KiB; a package's is a few kB.")
    return raw


@dataclass(frozen=True)
class Manifest:
    """What package.xml says: name, explicit build type (None when it has no <export><build_type>), and more."""

    name: str | None
    build_type: str | None = None
    depends: frozenset[str] = frozenset()
    groups: frozenset[str] = frozenset()  # <member_of_group>
    findings: tuple[str, ...] = ()


def name_only(raw: bytes) -> str | None:
    """The <name> of a package.xml expat refuses, found as text (roslaunch's $(find) still sees it by name)."""
    match = _NAME.search(raw[:65536])
    return match.group(1).decode("utf-8", "replace") if match else None


def _refuse_dtd(*_args: object) -> None:
    """No package.xml needs a DTD; refusing one keeps entity expansion (billion laughs) out entirely."""
    raise ManifestError("a package.xml needs no <!DOCTYPE>; remove it")


def read_manifest(path: Path) -> Manifest:
    """The package.xml at ``path``; a malformed one keeps the name found as text, with a finding saying why."""
    raw = read_bounded(path)
    texts: dict[str, list[str]] = {}
    stack: list[str] = []
    buffer: list[str] = []
    parser = expat.ParserCreate()

    def start(tag: str, _attrs: dict[str, str]) -> None:
        stack.append(tag)
        buffer.clear()

    def end(tag: str) -> None:
        texts.setdefault("/".join(stack), []).append("".join(buffer).strip())
        stack.pop()
        buffer.clear()

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = buffer.append
    parser.StartDoctypeDeclHandler = _refuse_dtd
    try:
        parser.Parse(raw, True)
    except (expat.ExpatError, ManifestError) as exc:
        where = f" line {exc.lineno}" if isinstance(exc, expat.ExpatError) else ""
        return Manifest(name_only(raw), findings=(
            f"package.xml{where} is not valid XML ({exc}): colcon would stop with 'Error(s) in package "
            f"'{path.parent.name}/package.xml''. Fix the file so every tag is closed.",))
    names = texts.get("package/name", [])
    build_types = texts.get("package/export/build_type", [])
    depends = frozenset(v for tag in _DEPENDS for v in texts.get(f"package/{tag}", []) if v)
    groups = frozenset(v for v in texts.get("package/member_of_group", []) if v)
    return Manifest(names[0] if names and names[0] else None, build_types[0] if build_types else None, depends,
                    groups)


@dataclass(frozen=True)
class SetupPy:
    """What setup.py hands setuptools: ``package_name``, console_scripts, the Python packages and where they are."""

    package_name: str | None = None
    console_scripts: tuple[str, ...] = ()
    packages: tuple[str, ...] | None = None  # None: find_packages() (or nothing said): folders with __init__.py
    excluded: tuple[str, ...] = ()  # find_packages(exclude=[...])
    package_dir: str = ""  # package_dir={'': 'src'} (catkin's layout)
    # data_files' (destination, sources) entries; None when they cannot be read without running setup.py
    data_files: tuple[DataFiles, ...] | None = ()


class _Constants:
    """Module-level ``name = 'text'`` assignments of setup.py, to evaluate simple expressions without running it."""

    def __init__(self, tree: ast.Module) -> None:
        self.names: dict[str, str] = {}
        for node in tree.body:
            if isinstance(node, ast.Assign):
                value = self.text(node.value)
                for target in node.targets:
                    if isinstance(target, ast.Name) and value is not None:
                        self.names[target.id] = value

    def text(self, node: ast.AST) -> str | None:
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return node.value
        if isinstance(node, ast.Name):
            return self.names.get(node.id)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            left, right = self.text(node.left), self.text(node.right)
            return left + right if left is not None and right is not None else None
        if isinstance(node, ast.JoinedStr):
            parts = [self.text(v.value) if isinstance(v, ast.FormattedValue) else self.text(v) for v in node.values]
            return "".join(parts) if all(p is not None for p in parts) else None  # type: ignore[arg-type]
        return None

    def texts(self, node: ast.AST) -> list[str] | None:
        if isinstance(node, (ast.List, ast.Tuple)):
            items = [self.text(e) for e in node.elts]
            return [i for i in items if i is not None]
        return None


def read_setup(path: Path) -> SetupPy:
    """setup.py's ``setup(...)`` (or catkin's ``generate_distutils_setup(...)``) keywords, read as a syntax tree."""
    raw = read_bounded(path)
    try:
        tree = parse(raw.decode("utf-8", "replace"))
    except _SYNTAX_ERRORS as exc:
        line = getattr(exc, "lineno", None)
        raise ManifestError(f"setup.py{f' line {line}' if line else ''} does not parse ({type(exc).__name__}): "
                            "colcon could not build the package. Fix the syntax error.") from None
    constants = _Constants(tree)
    scripts: list[str] = []
    packages: tuple[str, ...] | None = None
    excluded: list[str] = []
    package_dir = ""
    for node in ast.walk(tree):
        if isinstance(node, ast.Dict):
            for key, value in zip(node.keys, node.values):
                if key is not None and constants.text(key) == "console_scripts":
                    scripts += constants.texts(value) or []
        if not isinstance(node, ast.Call):
            continue
        for keyword in node.keywords:
            if keyword.arg == "packages":
                listed = constants.texts(keyword.value)
                if listed is not None:
                    packages = tuple(listed)
                elif isinstance(keyword.value, ast.Call):
                    for option in keyword.value.keywords:
                        if option.arg == "exclude":
                            excluded += constants.texts(option.value) or []
            elif keyword.arg == "package_dir" and isinstance(keyword.value, ast.Dict):
                for key, value in zip(keyword.value.keys, keyword.value.values):
                    if key is not None and constants.text(key) == "":
                        package_dir = constants.text(value) or ""
    return SetupPy(constants.names.get("package_name"), tuple(scripts), packages, tuple(excluded), package_dir,
                   read_data_files(tree, constants.text))

