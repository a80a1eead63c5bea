"""A submission's ROS packages as colcon and catkin would build them, read once as data and never built or run.

Each package has a name (package.xml), a build type (catkin, ament_python, ament_cmake), the executables `rosrun` /
`ros2 run` would find, the Python packages its build installs (what a node may import), its interface files and its
share folders. What the build would refuse or leave out becomes a finding worded as colcon or `ros2 run` would say it,
plus what to change; nothing here raises for a student's mistake.
"""
from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Literal, TypedDict

from grader.workspace import cmake
from grader.workspace.data_files import installed_share
from grader.workspace.manifest import (
    Manifest, ManifestError, SetupPy, name_only, read_manifest, read_regular, read_setup,
)

BuildType = Literal["catkin", "ament_python", "ament_cmake"]
SKIPPED_DIRS = frozenset({"build", "devel", "install", "log", "logs", "__pycache__", "node_modules", "__MACOSX"})
MAX_DEPTH = 6  # a workspace's src/<pkg>/package.xml is depth 2; deeper copies are not packages a build would use
MAX_PACKAGES = 64  # packages read in full; a course workspace has a handful
INTERFACE_KINDS = ("msg", "srv", "action")


class WorkspaceError(Exception):
    """The folder given as a workspace does not exist, or a package or executable asked for is not in it."""


@dataclass(frozen=True)
class Executable:
    """What `ros2 run <package> <name>` (or `rosrun`) starts: a script, or a console_scripts entry point's module."""

    name: str  # as the command line names it: scripts/move_circle.py installed by install(PROGRAMS) keeps its .py
    script: Path
    entry: str | None = None  # "module:function" of an ament_python console_scripts entry point
    # install(FILES) or install(DIRECTORY) without USE_SOURCE_PERMISSIONS installs it without the execute bit
    executable_install: bool = True


@dataclass(frozen=True)
class PythonPackage:
    """A Python package (or module) a node of the workspace may import once the workspace is built."""

    name: str  # the import name
    folder: Path  # the package's folder, or the module's file
    declared: bool = True  # False: a *_modules folder no ament_python_install_package() installs

    @property
    def root(self) -> Path:
        """The folder to put on sys.path so that ``import <name>`` finds it."""
        return self.folder.parent


@dataclass(frozen=True)
class Interface:
    """A .msg/.srv/.action file, and whether the build generates it (rosidl_generate_interfaces / add_*_files)."""

    path: Path
    kind: str  # msg, srv or action
    listed: bool


@dataclass(frozen=True)
class Package:
    """One ROS package of the submission, as its build would install it."""

    name: str
    folder: Path
    build_type: BuildType
    depends: frozenset[str] = frozenset()
    executables: tuple[Executable, ...] = ()
    python_packages: tuple[PythonPackage, ...] = ()
    interfaces: tuple[Interface, ...] = ()
    share: tuple[Path, ...] = ()  # folders (install(DIRECTORY)) and files (data_files) installed under share/<pkg>
    findings: tuple[str, ...] = ()
    setup_package_name: str | None = None  # ament_python: setup.py's package_name

    def executable_for(self, script: Path) -> Executable | None:
        """The executable that runs ``script``, when the build installs one."""
        target = script.resolve()
        return next((e for e in self.executables if e.script.resolve() == target), None)


class _Parts(TypedDict, total=False):
    """What a package's build files add to its Package (the fields beyond name, folder, build type, depends)."""

    executables: tuple[Executable, ...]
    python_packages: tuple[PythonPackage, ...]
    interfaces: tuple[Interface, ...]
    share: tuple[Path, ...]
    findings: tuple[str, ...]
    setup_package_name: str | None


def _build_type(manifest: Manifest, folder: Path) -> BuildType:
    """package.xml's <build_type>, else what the files say (catkin_pkg's default, catkin, when nothing does)."""
    if manifest.build_type in ("catkin", "ament_python", "ament_cmake"):
        return manifest.build_type  # type: ignore[return-value]
    if "catkin" in manifest.depends:
        return "catkin"
    has_cmake = (folder / "CMakeLists.txt").is_file()
    if (folder / "setup.py").is_file() and not has_cmake:
        return "ament_python"
    return "ament_cmake" if has_cmake and ("ament_cmake" in manifest.depends or _mentions_ament(folder)) else "catkin"


def _mentions_ament(folder: Path) -> bool:
    """Whether CMakeLists.txt builds with ament (for a package.xml that does not say, or cannot be read)."""
    try:
        return b"ament_cmake" in read_regular(folder / "CMakeLists.txt", cmake.MAX_BYTES)
    except OSError:
        return False


def _found_python_packages(base: Path, excluded: tuple[str, ...]) -> list[str]:
    """find_packages(): the top-level folders of ``base`` with an __init__.py, test folders left out as asked."""
    try:
        names = sorted(entry.name for entry in os.scandir(base) if entry.is_dir(follow_symlinks=False))
    except OSError:
        return []
    return [n for n in names if (base / n / "__init__.py").is_file() and n not in excluded and n.isidentifier()]


def _setup_python(folder: Path, setup: SetupPy) -> list[PythonPackage]:
    base = folder / setup.package_dir if setup.package_dir else folder
    names = list(setup.packages) if setup.packages is not None else _found_python_packages(base, setup.excluded)
    tops = dict.fromkeys(name.split(".")[0] for name in names if name)
    return [PythonPackage(name, base / name) for name in tops if (base / name).is_dir()]


def _ament_python(folder: Path, package: str) -> _Parts:
    try:
        setup = read_setup(folder / "setup.py")
    except ManifestError as exc:
        return {"findings": (str(exc),)}
    executables = []
    for spec in setup.console_scripts:
        name, sep, target = spec.partition("=")
        module, colon, function = target.strip().partition(":")
        if sep and colon and module.strip():
            script = folder.joinpath(*module.strip().split(".")).with_suffix(".py")
            executables.append(Executable(name.strip(), script, f"{module.strip()}:{function.strip()}"))
    # what data_files installs under share/<name>; when it cannot be read as data, the usual launch/ and config/
    share = tuple(p for p in (folder / "launch", folder / "config") if p.is_dir()) if setup.data_files is None \
        else installed_share(folder, package, setup.data_files)
    return {"executables": tuple(executables), "python_packages": tuple(_setup_python(folder, setup)),
            "share": share, "setup_package_name": setup.package_name}


def _files_of(folder: Path) -> list[Path]:
    try:
        return sorted(Path(e.path) for e in os.scandir(folder) if e.is_file())
    except OSError:
        return []


class _CMakeReading:
    """What ament_cmake or catkin would install from one package's CMakeLists.txt."""

    def __init__(self, folder: Path, name: str, catkin: bool) -> None:
        self.folder, self.name, self.catkin = folder, name, catkin
        here = str(folder)
        self.vars = cmake.Variables({"CMAKE_CURRENT_SOURCE_DIR": here, "CMAKE_CURRENT_LIST_DIR": here,
                                     "PROJECT_SOURCE_DIR": here, "CMAKE_SOURCE_DIR": here,
                                     "CATKIN_PACKAGE_BIN_DESTINATION": f"lib/{name}",
                                     "CATKIN_PACKAGE_SHARE_DESTINATION": f"share/{name}",
                                     "CATKIN_PACKAGE_PYTHON_DESTINATION": f"lib/python3/dist-packages/{name}"})
        self.executables: list[Executable] = []
        self.python: list[PythonPackage] = []
        self.listed: set[Path] = set()
        self.share: list[Path] = []
        self.findings: list[str] = []
        self.seen: set[str] = set()  # command names called
        self.found: set[str] = set()  # find_package() names

    def path(self, text: str) -> Path:
        return Path(os.path.normpath(self.folder / text))

    def bin_destination(self, destination: str) -> bool:
        """Whether files installed there are the package's executables (lib/<package>, as `ros2 run` looks)."""
        return destination.rstrip("/").endswith(f"lib/{self.name}")

    def install(self, args: list[str], line: int) -> None:
        kind = args[0].upper() if args else ""
        keywords = {"DESTINATION", "PERMISSIONS", "CONFIGURATIONS", "COMPONENT", "RENAME", "OPTIONAL",
                    "FILES_MATCHING", "PATTERN", "REGEX", "EXCLUDE", "USE_SOURCE_PERMISSIONS", "FILE_PERMISSIONS",
                    "DIRECTORY_PERMISSIONS", "MESSAGE_NEVER", "EXCLUDE_FROM_ALL"}
        items = []
        for arg in args[1:]:
            if arg.upper() in keywords:
                break
            items.append(arg)
        upper = [a.upper() for a in args]
        destination = args[upper.index("DESTINATION") + 1] if "DESTINATION" in upper[:-1] else ""
        if kind in ("PROGRAMS", "FILES"):
            # RENAME gives the one file its installed name, which `ros2 run` then takes
            rename = args[upper.index("RENAME") + 1] if "RENAME" in upper[:-1] and len(items) == 1 else None
            for item in items:
                path = self.path(item)
                if not path.is_file():
                    self.findings.append(
                        f"CMakeLists.txt line {line}: install({kind} {item}) names a file that does not exist: "
                        f"`colcon build` would stop with 'file INSTALL cannot find \"{path.name}\"'. Fix the path "
                        "or remove the line.")
                elif self.bin_destination(destination):
                    self.executables.append(Executable(rename or path.name, path,
                                                       executable_install=kind == "PROGRAMS"))
        elif kind == "DIRECTORY":
            for item in items:
                path = self.path(item)
                if not path.is_dir():
                    continue
                if self.bin_destination(destination):
                    keep = "USE_SOURCE_PERMISSIONS" in upper
                    self.executables += [Executable(f.name, f, executable_install=keep) for f in _files_of(path)]
                elif destination.startswith("share") or "SHARE_DESTINATION" in destination:
                    self.share.append(path)

    def python_package(self, args: list[str], line: int) -> None:
        if not args:
            return
        upper = [a.upper() for a in args]
        directory = args[upper.index("PACKAGE_DIR") + 1] if "PACKAGE_DIR" in upper[:-1] else args[0]
        folder = self.path(directory)
        if not (folder / "__init__.py").is_file():
            self.findings.append(
                f"CMakeLists.txt line {line}: `colcon build` would stop with 'ament_python_install_package() the "
                f"Python package folder '{folder.name}' doesn't contain an '__init__.py' file'. Create "
                f"{folder.name}/__init__.py (it may be empty), or fix the name in ament_python_install_package().")
        elif folder.name == args[0]:
            self.python.append(PythonPackage(args[0], folder))

    def interfaces(self, command: str, args: list[str], line: int) -> None:
        if command == "rosidl_generate_interfaces":
            listed = [a for a in args[1:] if a.endswith((".msg", ".srv", ".action", ".idl"))]
            self.listed.update(self.path(a) for a in listed)
            self.findings += [f"CMakeLists.txt line {line}: `colcon build` would stop with "
                              f"\"rosidl_generate_interfaces() the passed file '{a}' doesn't exist\". Fix the name "
                              f"or create {a}." for a in listed if not self.path(a).is_file()]
            return
        upper = [a.upper() for a in args]
        default = {"add_message_files": "msg", "add_service_files": "srv", "add_action_files": "action"}[command]
        base = args[upper.index("DIRECTORY") + 1] if "DIRECTORY" in upper[:-1] else default
        if "FILES" in upper:
            names = [a for a in args[upper.index("FILES") + 1:] if a.upper() not in ("DIRECTORY", "NOINSTALL")]
            self.listed.update(self.path(f"{base}/{n}") for n in names if n != base)
        else:  # without FILES, catkin takes every file of the folder
            self.listed.update(_files_of(self.path(base)))

    def read(self, commands: list[cmake.Command]) -> None:
        for command in commands:
            args = self.vars.arguments(command)
            self.seen.add(command.name)
            if command.name == "project" and args:
                self.vars.values["PROJECT_NAME"] = args[0]
            elif command.name == "set" and args:
                values = args[1:args.index("CACHE")] if "CACHE" in args else [a for a in args[1:]
                                                                               if a != "PARENT_SCOPE"]
                self.vars.values[args[0]] = ";".join(values)
            elif command.name == "find_package" and args:
                self.found.add(args[0])
            elif command.name in ("install", "catkin_install_python"):
                self.install(args, command.line)
            elif command.name == "ament_python_install_package":
                self.python_package(args, command.line)
            elif command.name == "ament_python_install_module" and args and self.path(args[0]).is_file():
                module = self.path(args[0])
                self.python.append(PythonPackage(module.stem, module))
            elif command.name in ("rosidl_generate_interfaces", "add_message_files", "add_service_files",
                                  "add_action_files"):
                self.interfaces(command.name, args, command.line)
        if self.catkin:
            return
        project = self.vars.values.get("PROJECT_NAME")
        if "ament_python_install_package" in self.seen and "ament_cmake_python" not in self.found:
            self.findings.append(
                "`colcon build` would stop with 'Unknown CMake command \"ament_python_install_package\"'. Add "
                "`find_package(ament_cmake_python REQUIRED)` to CMakeLists.txt, before that line.")
        if "ament_package" not in self.seen:
            self.findings.append(
                f"CMakeLists.txt never calls ament_package(): the package is not registered when it is built, so "
                f"`ros2 run {self.name} ...` would say \"Package '{self.name}' not found\". Add `ament_package()` as "
                "its last line.")
        elif project is not None and project != self.name:
            self.findings.append(
                f"`colcon build` would stop with \"ament_package() package name '{self.name}' in package.xml does "
                f"not match current PROJECT_NAME '{project}'\". Write project({self.name}) in CMakeLists.txt.")


def _modules_folders(folder: Path, installed: set[str]) -> list[PythonPackage]:
    """The package's own ``*_modules`` folders that no ament_python_install_package() installs (the template's)."""
    try:
        names = sorted(e.name for e in os.scandir(folder) if e.is_dir(follow_symlinks=False))
    except OSError:
        return []
    return [PythonPackage(n, folder / n, declared=False) for n in names
            if n.endswith("_modules") and n not in installed and (folder / n / "__init__.py").is_file()]


def _interface_files(folder: Path, listed: set[Path]) -> tuple[Interface, ...]:
    found = [Interface(path, kind, path in listed) for kind in INTERFACE_KINDS
             for path in _files_of(folder / kind) if path.suffix == f".{kind}"]
    return tuple(found)


def _cmake_package(folder: Path, name: str, manifest: Manifest, build_type: BuildType) -> _Parts:
    reading = _CMakeReading(folder, name, build_type == "catkin")
    try:
        reading.read(cmake.read(folder / "CMakeLists.txt"))
    except cmake.CMakeError as exc:
        return {"findings": (f"{exc} `colcon build` would stop there: fix CMakeLists.txt.",)}
    python = list(reading.python)
    if build_type == "catkin" and "catkin_python_setup" in reading.seen and (folder / "setup.py").is_file():
        try:
            python += _setup_python(folder, read_setup(folder / "setup.py"))
        except ManifestError as exc:
            reading.findings.append(str(exc))
    python += _modules_folders(folder, {p.name for p in python})
    interfaces = _interface_files(folder, reading.listed)
    findings = list(reading.findings)
    if build_type == "ament_cmake" and "rosidl_generate_interfaces" in reading.seen \
            and "rosidl_interface_packages" not in manifest.groups:
        findings.append("`colcon build` would stop with \"Packages installing interfaces must include "
                        "'<member_of_group>rosidl_interface_packages</member_of_group>' in their package.xml\". Add "
                        "that line to package.xml.")
    for item in interfaces:
        if not item.listed:
            where = "rosidl_generate_interfaces()" if build_type == "ament_cmake" else \
                {"msg": "add_message_files()", "srv": "add_service_files()", "action": "add_action_files()"}[item.kind]
            findings.append(f"{item.kind}/{item.path.name} is not listed in {where} in CMakeLists.txt, so it is "
                            f"never built: importing {name}.{item.kind}.{item.path.stem} would fail. Add "
                            f"\"{item.kind}/{item.path.name}\" there.")
    return {"executables": tuple(reading.executables), "python_packages": tuple(python), "interfaces": interfaces,
            "share": tuple(reading.share), "findings": tuple(findings)}


def read_package(folder: Path) -> Package | None:
    """The package whose package.xml is in ``folder`` (None when it has none, or no name)."""
    if not (folder / "package.xml").is_file():
        return None
    try:
        manifest = read_manifest(folder / "package.xml")
    except ManifestError as exc:
        name = package_name(folder)
        return Package(name, folder, "catkin", findings=(str(exc),)) if name else None
    if manifest.name is None:
        return None
    build_type = _build_type(manifest, folder)
    parts: _Parts
    if build_type == "ament_python":
        parts = _ament_python(folder, manifest.name)
    elif (folder / "CMakeLists.txt").is_file():
        parts = _cmake_package(folder, manifest.name, manifest, build_type)
    elif build_type == "ament_cmake":
        parts = {"findings": ("package.xml says ament_cmake, but the package has no CMakeLists.txt: `colcon build` "
                              "would stop. Add the CMakeLists.txt of your package template.",)}
    else:
        parts = {}
    python, outside = _inside(folder, parts.get("python_packages", ()))
    parts["python_packages"] = python
    parts["findings"] = manifest.findings + tuple(parts.get("findings", ())) + tuple(
        f"The Python package {item.name} is installed from outside the package {manifest.name} "
        f"({item.folder}); the grader imports only modules inside the submission's packages: move it into "
        f"{manifest.name}/." for item in outside)
    return Package(manifest.name, folder, build_type, manifest.depends, **parts)


def _inside(folder: Path, items: tuple[PythonPackage, ...]) -> tuple[tuple[PythonPackage, ...], list[PythonPackage]]:
    """The Python packages that lie inside the package's folder (links resolved), and those that do not: a node's
    sandbox shows only the submission, never a folder of the grader's machine that a path or link leads to."""
    base = folder.resolve()
    inside = tuple(item for item in items if base in item.folder.resolve().parents)
    return inside, [item for item in items if item not in inside]


def package_name(folder: Path) -> str | None:
    """The ``<name>`` in ``folder/package.xml`` as text, or None (a cheap look that reads nothing else)."""
    try:
        return name_only(read_regular(folder / "package.xml", 65536))
    except OSError:
        return None


def enclosing_folder(path: Path) -> Path | None:
    """The nearest folder at or above ``path`` that holds a ``package.xml``."""
    for folder in [path, *path.parents] if path.is_dir() else path.parents:
        if (folder / "package.xml").is_file():
            return folder
    return None


class Workspace:
    """The packages under one folder by name (the shallowest, then the first in path order, when two share one),
    each read in full only when asked for."""

    def __init__(self, root: Path, folders: dict[str, Path]) -> None:
        self.root = root
        self.folders = folders
        self._read: dict[Path, Package | None] = {}

    def package_at(self, folder: Path) -> Package | None:
        """The package in ``folder`` (read once, however the folder is spelled)."""
        key = folder.resolve()
        if key not in self._read:
            self._read[key] = read_package(folder)
        return self._read[key]

    def package(self, name: str) -> Package | None:
        folder = self.folders.get(name)
        return self.package_at(folder) if folder is not None else None

    def enclosing(self, path: Path) -> Package | None:
        """The package a file or folder belongs to."""
        folder = enclosing_folder(path.resolve())
        return self.package_at(folder) if folder is not None else None

    def packages(self) -> Iterator[Package]:
        """Every package, read in full (at most MAX_PACKAGES, in name order)."""
        for name in sorted(self.folders)[:MAX_PACKAGES]:
            package = self.package(name)
            if package is not None:
                yield package

    def executable(self, package: str, name: str) -> Executable:
        """What `ros2 run <package> <name>` (an ament package) or `rosrun` (catkin) starts, or WorkspaceError with
        what they would print: ament finds only what the build installs, rosrun any executable file of the package."""
        found = self.package(package)
        if found is None:
            raise WorkspaceError(f"Package '{package}' not found")
        if found.build_type != "catkin":
            match = next((e for e in found.executables if e.name == name), None)
            if match is None:
                raise WorkspaceError(f"No executable found (`ros2 run {package} {name}`: the build of {package} "
                                     f"installs {', '.join(sorted(e.name for e in found.executables)) or 'none'})")
            return match
        for folder, dirs, files in os.walk(found.folder):
            depth = len(Path(folder).relative_to(found.folder).parts)
            dirs[:] = [] if depth >= MAX_DEPTH else sorted(d for d in dirs if not d.startswith(".")
                                                           and d not in SKIPPED_DIRS)
            if name in files and os.access(Path(folder) / name, os.X_OK):
                return Executable(name, Path(folder) / name)
        raise WorkspaceError(f"[rosrun] Couldn't find executable named {name} below {found.folder}")

    def python_packages(self) -> list[PythonPackage]:
        """Every Python package the workspace's build would install, by import name (the first one of a name)."""
        found: dict[str, PythonPackage] = {}
        for package in self.packages():
            for item in package.python_packages:
                found.setdefault(item.name, item)
        return list(found.values())


def read_workspace(root: Path) -> Workspace:
    """The packages at or below ``root`` (a folder, or a file whose package is the workspace), found by walking at
    most MAX_DEPTH folders down, skipping build output and hidden folders."""
    if not root.exists():
        raise WorkspaceError(f"{root} does not exist")
    start = root if root.is_dir() else root.parent
    found: list[tuple[int, str, str, Path]] = []
    if root.is_dir():
        for folder, dirs, files in os.walk(start):
            depth = len(Path(folder).relative_to(start).parts)
            dirs[:] = [] if depth >= MAX_DEPTH else [d for d in dirs if not d.startswith(".") and d not in SKIPPED_DIRS]
            if "package.xml" in files:
                name = package_name(Path(folder))
                if name:
                    found.append((depth, folder, name, Path(folder)))
    folders: dict[str, Path] = {}
    for _, _, name, folder in sorted(found):
        folders.setdefault(name, folder)
    above = enclosing_folder(root)
    if above is not None:  # a script, or a folder inside a package: its own package is part of the workspace
        name = package_name(above)
        if name:
            folders.setdefault(name, above)
    return Workspace(start, folders)
