"""A submission's .msg/.srv/.action files parsed by rosbags into type definitions, bounded and checked as data.

What colcon or catkin would refuse (a type that contains itself, an unknown field type, a file that is not a
definition), what rosgrade will not take (a package that shadows a built-in one, a file or type too large to be a
course's) and what it drops because of those becomes a finding; nothing here raises for a student's file.
"""
from __future__ import annotations

import re
import sys
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from rosbags.typesys import get_types_from_msg
from rosbags.typesys.base import Nodetype

from grader.interfaces.defaults import field_defaults
from grader.interfaces.derived import ros1_action_types
from grader.workspace.manifest import read_regular
from grader.workspace.model import Package

MAX_FILE_BYTES = 32 * 1024   # a course's interface file is a few hundred bytes; rosbags parses ~10k lines a second
MAX_TOTAL_BYTES = 256 * 1024
MAX_FIELDS = 1000            # fields and constants of one type
MAX_TYPES = 500
MAX_NESTING = 32             # student types inside student types
MAX_ELEMENTS = 1_000_000     # fixed-size array elements a message holds, through nesting
SEPARATOR = re.compile(r"^---\s*$", re.MULTILINE)
_NAME = re.compile(r"^[A-Z][A-Za-z0-9]*$")
_PACKAGE = re.compile(r"^[a-z][a-z0-9_]*$")
# Names a generated package may not take in the node: the client libraries' own and what a node imports besides.
_RESERVED = frozenset({"numpy", "rclpy", "rospy", "genpy", "rosidl_parser", "rosidl_runtime_py", "launch",
                       "launch_ros", "tf2_ros", "tf", "actionlib", "rosgraph", "roslib", "rospkg"})
ACTION_PARTS = ("Goal", "Result", "Feedback")

TypeDef = tuple[list, list]  # rosbags: (constants, fields)


@dataclass
class InterfaceSet:
    """The student's interface types of one ROS version, as data (picklable): what a run's catalog adds."""

    flavour: str                                            # "ros1" (pkg/msg/Name, pkg/NameRequest) or "ros2"
    types: dict[str, TypeDef] = field(default_factory=dict)  # rosbags name -> definition, parts of srv/action too
    services: dict[str, tuple[str, str]] = field(default_factory=dict)  # srv type -> (request, response) types
    actions: dict[str, tuple[str, ...]] = field(default_factory=dict)   # action type -> Goal, Result, Feedback
    defaults: dict[str, dict[str, object]] = field(default_factory=dict)  # type -> field -> .msg default value
    findings: list[str] = field(default_factory=list)
    payload: dict | None = None  # what a node is given at START (grader.interfaces.node_payload)

    def __bool__(self) -> bool:
        return bool(self.types)


@dataclass
class _Parsed:
    """What one file gave: its types, where they came from, and what it references."""

    where: str
    types: dict[str, TypeDef]
    sections: list[str]


def _strip(text: str) -> str:
    return "\n".join(line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#"))


def _parse_part(text: str, name: str, where: str) -> tuple[TypeDef | None, str | None]:
    """One message's definition (rosbags), parsed as ``pkg/msg/<Name>`` so relative names resolve to the package's
    msg folder, as rosidl and genmsg resolve them."""
    package, _, short = name.split("/")
    lines = _strip(text).splitlines()
    if len(lines) > MAX_FIELDS:
        return None, f"{where} declares {len(lines)} fields and constants; rosgrade takes at most {MAX_FIELDS} in " \
                     "one type. Split it into smaller messages."
    if any(line.startswith(("MSG:", "=")) for line in lines):
        return None, f"{where} holds other message definitions ('MSG:' or '===' lines), which rosidl would refuse: " \
                     "put each type in its own file."
    try:
        parsed = get_types_from_msg(text, f"{package}/msg/{short}")
    except Exception as exc:  # noqa: BLE001 - the file is data; rosbags raises its own parse errors
        return None, f"{where} is not a valid definition ({str(exc).splitlines()[0][:200]}); `colcon build` would " \
                     "stop there."
    ((_, typedef),) = parsed.items()
    for fname, _ in typedef[1]:
        if not re.fullmatch(r"[a-z][a-z0-9_]*", fname) or fname.endswith("_") or "__" in fname:
            return None, f"{where}: '{fname}' is not a valid field name (lower case letters, digits and single " \
                         "underscores, starting with a letter); rosidl would refuse it."
    return typedef, None


def _parts(kind: str, package: str, stem: str, flavour: str) -> list[str]:
    """The type names a file defines, in the flavour's spelling (rosbags' ``pkg/ns/Name``)."""
    if kind == "msg":
        return [f"{package}/msg/{stem}"]
    if kind == "srv":
        return [f"{package}/srv/{stem}_{p}" if flavour == "ros2" else f"{package}/msg/{stem}{p}"
                for p in ("Request", "Response")]
    return [f"{package}/action/{stem}_{p}" if flavour == "ros2" else f"{package}/msg/{stem}{p}"
            for p in ACTION_PARTS]


def _read_file(path: Path, kind: str, package: str, flavour: str,
               budget: list[int]) -> tuple[_Parsed | None, str | None]:
    where = f"{package}/{kind}/{path.name}"
    if not _NAME.match(path.stem):
        return None, f"{where}: '{path.stem}' is not a valid interface name (CamelCase letters and digits); rosidl " \
                     "would refuse it. Rename the file."
    try:
        raw = read_regular(path, MAX_FILE_BYTES + 1)
    except OSError as exc:
        return None, f"{where} cannot be read ({exc.strerror or exc})."
    if len(raw) > MAX_FILE_BYTES:
        return None, f"{where} is larger than {MAX_FILE_BYTES >> 10} KiB; a course's interface file is a few " \
                     "hundred bytes. It was left out."
    budget[0] -= len(raw)
    if budget[0] < 0:
        return None, f"{where} was left out: the submission's interface files exceed {MAX_TOTAL_BYTES >> 10} KiB."
    text = raw.decode("utf-8", "replace")
    sections = SEPARATOR.split(text)
    wanted = {"msg": 1, "srv": 2, "action": 3}[kind]
    if len(sections) != wanted:
        return None, f"{where} has {len(sections) - 1} '---' lines where a .{kind} file has {wanted - 1}; " \
                     "`colcon build` would stop there."
    names = _parts(kind, package, path.stem, flavour)
    types: dict[str, TypeDef] = {}
    for section, name in zip(sections, names):
        typedef, problem = _parse_part(section, name, where)
        if problem:
            return None, problem
        assert typedef is not None
        types[name] = typedef
    if kind == "action" and flavour == "ros1":
        types.update(ros1_action_types(package, path.stem))
    return _Parsed(where, types, sections), None


def _references(typedef: TypeDef) -> Iterable[str]:
    for _, desc in typedef[1]:
        node, detail = desc
        if node in (Nodetype.ARRAY, Nodetype.SEQUENCE):
            node, detail = detail[0]
        if node == Nodetype.NAME:
            yield detail


def _elements(typedef: TypeDef, sizes: dict[str, int]) -> int:
    """Fixed-size elements one message holds (a sequence counts one: its length is the sender's)."""
    total = 0
    for _, (node, detail) in typedef[1]:
        count = 1
        if node == Nodetype.ARRAY:
            (node, detail), count = detail
        elif node == Nodetype.SEQUENCE:
            (node, detail), count = detail[0], 1
        total += count * (sizes.get(detail, 1) if node == Nodetype.NAME else 1)
    return total


def _shown(name: str) -> str:
    package, namespace, short = name.split("/")
    return f"{package}/{short}" if namespace == "msg" else name


class _Checker:
    """Drops what the build or rosgrade would refuse, with a finding each, until what is left stands on its own."""

    def __init__(self, builtin: frozenset[str], parsed: list[_Parsed], findings: list[str]) -> None:
        self.builtin = builtin
        self.files = parsed
        self.findings = findings

    def run(self) -> dict[str, TypeDef]:
        types = {name: typedef for item in self.files for name, typedef in item.types.items()}
        where = {name: item.where for item in self.files for name in item.types}
        for name in list(types):
            missing = [ref for ref in _references(types.get(name, ([], []))) if ref not in where
                       and ref not in self.builtin]
            if missing:
                self.findings.append(f"{where[name]}: unknown type {_shown(missing[0])}; `colcon build` would stop "
                                     "there. Add the package that defines it to the workspace, or fix the name.")
                self._drop(types, where, name)
        self._drop_dependents(types, where)  # their own finding names the cause
        self._cycles_and_sizes(types, where)
        self._drop_dependents(types, where)
        return types

    def _drop(self, types: dict[str, TypeDef], where: dict[str, str], name: str) -> None:
        """A file's types go together (a service without its response is no service)."""
        file = where[name]
        for other in [n for n in types if where[n] == file]:
            del types[other]

    def _cycles_and_sizes(self, types: dict[str, TypeDef], where: dict[str, str]) -> None:
        """Refuses types in a loop, nested too deep or too large: leaves first (Kahn's order, no recursion), so a
        long chain costs no stack; what is left over after it is in a loop or uses one."""
        refs = {name: sorted({r for r in _references(typedef) if r in types}) for name, typedef in types.items()}
        users: dict[str, list[str]] = {name: [] for name in types}
        for name, used in refs.items():
            for ref in used:
                users[ref].append(name)
        pending = {name: len(used) for name, used in refs.items()}
        ready = sorted((name for name, count in pending.items() if not count), reverse=True)
        depth: dict[str, int] = {}
        sizes: dict[str, int] = {}
        refused: set[str] = set()
        while ready:
            name = ready.pop()
            depth[name] = max((depth[ref] + 1 for ref in refs[name]), default=0)
            sizes[name] = _elements(types[name], sizes)
            if any(ref in refused for ref in refs[name]):
                refused.add(name)  # the type it uses has the finding
            elif depth[name] > MAX_NESTING:
                self.findings.append(f"{where[name]}: {_shown(name)} nests {depth[name]} of the submission's types "
                                     f"inside each other; rosgrade takes at most {MAX_NESTING}.")
                refused.add(name)
            elif sizes[name] > MAX_ELEMENTS:
                self.findings.append(f"{where[name]}: {_shown(name)} holds {sizes[name]} fixed-size elements; "
                                     f"rosgrade takes at most {MAX_ELEMENTS} in one message. Use a sequence.")
                refused.add(name)
            for user in users[name]:
                pending[user] -= 1
                if not pending[user]:
                    ready.append(user)
        looped = sorted(name for name in types if name not in depth)
        seen: set[str] = set()
        for start in looped:
            path = [start]
            while True:  # each left-over type uses another left-over one: walk until one repeats
                following = next(ref for ref in refs[path[-1]] if ref not in depth)
                if following in path:
                    loop = path[path.index(following):] + [following]
                    break
                path.append(following)
            if not seen.intersection(loop):
                self.findings.append(f"{where[loop[0]]}: {' -> '.join(_shown(n) for n in loop)} contains itself, so "
                                     "it would never end; rosidl refuses such a type. Use a sequence of ids instead.")
            seen.update(path)
        for name in sorted(refused | set(looped)):
            if name in types:
                self._drop(types, where, name)

    def _drop_dependents(self, types: dict[str, TypeDef], where: dict[str, str]) -> None:
        """Drops, until none is left, the types that use a type that was dropped."""
        changed = True
        while changed:
            changed = False
            for name in list(types):
                if name in types and any(ref not in types and ref not in self.builtin
                                         for ref in _references(types[name])):
                    self._drop(types, where, name)
                    changed = True


def _reserved(flavour: str) -> frozenset[str]:
    from grader.nodelib import import_roots  # noqa: PLC0415 - only to list the node's own top-level names
    names = set(_RESERVED) | set(sys.stdlib_module_names)
    for root in import_roots(flavour):
        if root.is_dir():
            names.update(p.stem for p in root.iterdir() if not p.name.startswith(("_", ".")))
    return frozenset(names)


def read_interfaces(packages: Iterable[Package], flavour: str, builtin: Iterable[str]) -> InterfaceSet:
    """The interface types the packages' builds generate (files listed in rosidl_generate_interfaces or add_*_files),
    for a run of ``flavour``; ``builtin`` are the type names (rosbags' spelling) the run knows without them."""
    builtin = frozenset(builtin)
    builtin_packages = {name.split("/")[0] for name in builtin}
    reserved = _reserved(flavour)
    result = InterfaceSet(flavour)
    parsed: list[_Parsed] = []
    budget = [MAX_TOTAL_BYTES]
    count = 0
    for package in packages:
        listed = [item for item in package.interfaces if item.listed]
        if not listed or (package.build_type == "catkin") != (flavour == "ros1"):
            continue
        if package.name in builtin_packages or package.name in reserved or not _PACKAGE.match(package.name):
            why = "a package ROS already has" if package.name in builtin_packages else \
                "a name the node's own libraries use" if package.name in reserved else "not a valid package name"
            result.findings.append(f"package {package.name} is {why}: its interfaces would shadow or break the "
                                   f"built-in ones, so rosgrade leaves them out. Rename the package (e.g. "
                                   f"{package.name.strip('_')}_interfaces).")
            continue
        for item in sorted(listed, key=lambda i: (i.kind, i.path.name)):
            count += 1
            if count > MAX_TYPES:
                result.findings.append(f"the submission has more than {MAX_TYPES} interface files; the rest were "
                                       "left out.")
                break
            found, problem = _read_file(item.path, item.kind, package.name, flavour, budget)
            if problem:
                result.findings.append(problem)
            elif found is not None:
                parsed.append(found)
                if flavour == "ros2":  # ROS 1 has no field defaults
                    for name, section in zip(found.types, found.sections):
                        defaults = field_defaults(section, found.types[name])
                        if defaults:
                            result.defaults[name] = defaults
    result.types = _Checker(builtin, parsed, result.findings).run()
    for item in parsed:
        names = list(item.types)
        if not all(n in result.types for n in names):
            continue
        if len(names) == 2:
            service = names[0].rsplit("_", 1)[0] if flavour == "ros2" else names[0][:-len("Request")]
            result.services[service] = (names[0], names[1])
        elif len(names) in (3, 7):  # ROS 1: its Goal, Result and Feedback, then the four messages around them
            result.actions[names[0].rsplit("_", 1)[0] if flavour == "ros2" else names[0][:-len("Goal")]] = \
                tuple(names[:3])
    result.defaults = {k: v for k, v in result.defaults.items() if k in result.types}
    return result

