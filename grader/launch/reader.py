"""Read a roslaunch XML file (and what it includes) into a Launch, following roslaunch's rules.

Args are scoped to their file and group; ``$(find)`` sees the submission's packages and the simulated ones;
parameters are resolved to global names as roslaunch resolves them (``~name`` inside or before a node is the
node's own); remaps apply to the nodes that follow in the same scope. Anything that would run a program at launch
time (``command=``, ``<machine>``, ``<test>``, ``launch-prefix``) is refused with a message that says so.
"""
from __future__ import annotations

import hashlib
import shlex
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path

import yaml

from grader.launch import known, names
from grader.launch.model import Launch, LaunchError, LaunchNode, Where, WorldLaunch
from grader.launch.substitution import Scope, SubstitutionError, substitute
from grader.launch.values import FALSE as _FALSE, TRUE as _TRUE, ValueTooLarge, convert, load_yaml
from grader.launch.xmltree import Element, XmlError, parse

MAX_INCLUDE_DEPTH = 16
MAX_FILES = 64  # files read for one launch, includes counted each time: keeps a self-including fan-out small


@dataclass
class _Context:
    """Where the reader is: the file, the namespace, and what this scope has declared so far."""

    file: Path
    ns: str
    args: dict[str, str | None]
    remaps: list[tuple[str, str]] = field(default_factory=list)
    private_params: dict[str, object] = field(default_factory=dict)  # ~name -> value, for the nodes that follow

    def child(self, ns: str | None = None, file: Path | None = None, fresh_args: bool = False) -> _Context:
        namespace = self.ns if not ns else names.global_ns(names.join(self.ns, ns))
        return _Context(file or self.file, namespace, {} if fresh_args else dict(self.args), list(self.remaps),
                        dict(self.private_params))


class Reader:
    """Reads one top-level launch file; `read()` returns the Launch."""

    def __init__(self, packages: Mapping[str, Path], env: Mapping[str, str], confine_to: Path | None) -> None:
        self.packages = dict(packages)
        self.env = dict(env)
        self.confine_to = confine_to.resolve() if confine_to is not None else None
        self.anon: dict[str, str] = {}
        self.launch: Launch | None = None
        self.depth = 0
        self.files_read = 0

    def read(self, path: Path, args: Mapping[str, str]) -> Launch:
        path = path.resolve()
        self.launch = Launch(file=path)
        if self.confine_to is not None and not path.is_relative_to(self.confine_to):
            raise LaunchError(f"{path.name} is a link to a file outside your submission; submit the file itself")
        root = self._parse(path, None)
        context = _Context(path, "/", {})
        declared = self._scope_file(root, context, dict(args))
        self.launch.args = {name: context.args.get(name) for name in sorted(declared)}
        return self.launch

    # -- files ---------------------------------------------------------------------------------------------------
    def _read_text(self, path: Path, what: str) -> str:
        """A file a launch file names, read only from inside the submission when the reader is confined to it."""
        real = path.resolve()
        if self.confine_to is not None and not real.is_relative_to(self.confine_to):
            raise LaunchError(f"{what} reads {path}, which is outside your submission; the grader reads only your "
                              "own files (use $(find your_package)/...)")
        try:
            return real.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise LaunchError(f"{what}: cannot read {path}: {getattr(exc, 'strerror', None) or exc}") from None

    def _parse(self, path: Path, where: Where | None) -> Element:
        at = f" (included from {where})" if where else ""
        try:
            root = parse(path)
        except FileNotFoundError:
            raise LaunchError(f"launch file {path} not found{at}", located=True) from None
        except IsADirectoryError:
            raise LaunchError(f"{path} is a folder, not a launch file{at}", located=True) from None
        except OSError as exc:
            raise LaunchError(f"cannot read {path}{at}: {exc.strerror or exc}", located=True) from None
        except XmlError as exc:
            raise LaunchError(f"{path.name}: invalid XML: {exc}{at}", located=True) from None
        if root.tag != "launch":
            raise LaunchError(f"{path.name} line {root.line}: the root tag is <{root.tag}>; a launch file's root "
                              "tag must be <launch>", located=True)
        return root

    def _scope_file(self, root: Element, context: _Context, passed: dict[str, str]) -> set[str]:
        """Read a file's elements with `passed` args; return the names of the args it declared."""
        declared: set[str] = set()
        self._children(root, context, passed, declared)
        return declared

    # -- element dispatch ----------------------------------------------------------------------------------------
    def _children(self, element: Element, context: _Context, passed: dict[str, str], declared: set[str]) -> None:
        for child in element.children:
            where = Where(context.file, child.line)
            try:
                if not self._active(child, context):
                    continue
                handler = {"arg": self._arg, "group": self._group, "node": self._node, "param": self._param,
                           "rosparam": self._rosparam, "remap": self._remap, "include": self._include,
                           "env": self._env}.get(child.tag)
                if child.tag in ("machine", "test"):
                    raise LaunchError(self._refused(child.tag))
                if handler is None:
                    self.launch.notes.append(f"{where}: <{child.tag}> is not a roslaunch tag; it was ignored")
                    continue
                handler(child, context, passed, declared)
            except SubstitutionError as exc:
                raise LaunchError(f"{where}: {exc}", located=True) from None
            except LaunchError as exc:
                if exc.located:
                    raise
                raise LaunchError(f"{where}: {exc}", located=True) from None

    @staticmethod
    def _refused(tag: str) -> str:
        if tag == "machine":
            return "<machine> starts nodes on other computers; the grader runs everything on one machine: remove it"
        return "<test> starts a rostest, which the grader does not run: use <node> for the nodes to grade"

    def _active(self, element: Element, context: _Context) -> bool:
        if "if" in element.attrs and "unless" in element.attrs:
            raise LaunchError(f"<{element.tag}> has both if= and unless=; use one")
        for key, wanted in (("if", True), ("unless", False)):
            if key in element.attrs:
                value = self._sub(element.attrs[key], context).lower()
                if value not in _TRUE + _FALSE:
                    raise LaunchError(f"{key}=\"{element.attrs[key]}\" is '{value}'; expected true or false")
                return (value in _TRUE) == wanted
        return True

    # -- substitutions -------------------------------------------------------------------------------------------
    def _scope(self, context: _Context) -> Scope:
        def arg(name: str) -> str:
            if name not in context.args:
                raise SubstitutionError(f"arg '{name}' is not defined: declare it with <arg name=\"{name}\" "
                                        "default=\"...\"/> before using it")
            value = context.args[name]
            if value is None:
                raise SubstitutionError(f"{context.file.name} requires the '{name}' arg to be set: pass "
                                        f"{name}:=value, or give the <arg> a default")
            return value

        return Scope(arg=arg, find=self._find, anon=self._anon, env=self.env, dirname=str(context.file.parent),
                     arg_names=lambda: {k: v for k, v in context.args.items() if v is not None})

    def _sub(self, text: str, context: _Context) -> str:
        return substitute(text, self._scope(context))

    def _find(self, package: str) -> str:
        if package in self.packages:
            return str(self.packages[package])
        try:
            return known.package_path(package)
        except known.UnknownPackage as exc:
            mine = ", ".join(sorted(self.packages)) or "none found (no package.xml)"
            raise SubstitutionError(f"$(find {package}): {exc}; your packages: {mine}") from None

    def _anon(self, name: str) -> str:
        # Real roslaunch appends host, pid and a random number; the grader's is the same for every run.
        if name not in self.anon:
            digest = int(hashlib.sha256(name.encode()).hexdigest()[:15], 16)
            self.anon[name] = f"{name}_rosgrade_1_{digest}"
        return self.anon[name]

    def _attr(self, element: Element, context: _Context, key: str, required: bool = False) -> str | None:
        if key not in element.attrs:
            if required:
                raise LaunchError(f"<{element.tag}> needs a {key}= attribute")
            return None
        return self._sub(element.attrs[key], context)

    def _flag(self, element: Element, context: _Context, key: str) -> bool:
        value = (self._attr(element, context, key) or "false").lower()
        if value not in _TRUE + _FALSE:
            raise LaunchError(f"{key}=\"{value}\" on <{element.tag}>: expected true or false")
        return value in _TRUE

    # -- tags ----------------------------------------------------------------------------------------------------
    def _arg(self, element: Element, context: _Context, passed: dict[str, str], declared: set[str]) -> None:
        name = self._attr(element, context, "name", required=True)
        if "value" in element.attrs and "default" in element.attrs:
            raise LaunchError(f"<arg name=\"{name}\"> has both value= and default=; use one")
        if name in declared:
            raise LaunchError(f"arg '{name}' has already been declared")
        declared.add(name)
        if "value" in element.attrs:
            if name in passed:
                raise LaunchError(f"cannot override arg '{name}', which has already been set (it has value=; "
                                  "use default= for an arg that can be passed)")
            context.args[name] = self._attr(element, context, "value")
        elif "default" in element.attrs:
            context.args[name] = passed[name] if name in passed else self._attr(element, context, "default")
        else:
            context.args[name] = passed.get(name)

    def _group(self, element: Element, context: _Context, passed: dict[str, str], declared: set[str]) -> None:
        child = context.child(self._attr(element, context, "ns"))
        self._children(element, child, passed, set(declared))

    def _remap(self, element: Element, context: _Context, *_: object) -> None:
        _add_remap(context.remaps, self._remap_pair(element, context))

    def _remap_pair(self, element: Element, context: _Context) -> tuple[str, str]:
        source = names.canonical(self._attr(element, context, "from", required=True))
        target = names.canonical(self._attr(element, context, "to", required=True))
        if not source or not target:
            raise LaunchError("remap from= and to= cannot be empty")
        return source, target

    def _env(self, element: Element, context: _Context, *_: object) -> None:
        name = self._attr(element, context, "name", required=True)
        self.launch.notes.append(f"{Where(context.file, element.line)}: <env name=\"{name}\"> is ignored by the "
                                 "grader (nodes run with a fixed environment)")

    def _param(self, element: Element, context: _Context, *_: object, node: str | None = None) -> None:
        name = self._attr(element, context, "name", required=True)
        sources = [k for k in ("value", "textfile", "binfile", "command") if k in element.attrs]
        if len(sources) != 1:
            raise LaunchError(f"<param name=\"{name}\"> must have exactly one of value=, textfile=, binfile=, "
                              "command=")
        source = sources[0]
        if source == "command":
            raise LaunchError(f"<param name=\"{name}\" command=...> runs a program at launch time, which the "
                              "grader does not do: put the value in value= or a YAML file loaded with <rosparam>")
        if source == "binfile":
            raise LaunchError(f"<param name=\"{name}\" binfile=...> is not supported by the grader: use value= "
                              "or textfile=")
        if source == "textfile":
            value: object = self._read_text(Path(self._attr(element, context, "textfile")),
                                            f"<param name=\"{name}\" textfile=...>")
        else:
            text = self._attr(element, context, "value")
            kind = self._attr(element, context, "type") or "auto"
            try:
                value = convert(text, kind)
            except ValueError as exc:
                raise LaunchError(f"<param name=\"{name}\" value=\"{text}\" type=\"{kind}\">: {exc}") from None
        # A <param> keeps a dictionary (type="yaml") as one value; only <rosparam> unrolls it.
        if node is not None:  # roslaunch makes every name inside <node> private, even a global one
            self.launch.params[names.canonical(names.join(node + "/", name.lstrip("~/")))] = value
        elif name.startswith("~"):
            context.private_params[name[1:]] = value
        else:
            self.launch.params[names.canonical(names.join(context.ns, name))] = value

    def _unroll(self, key: str, value: object) -> None:
        """Add what <rosparam> loaded: a dictionary becomes one parameter per leaf, as roslaunch unrolls it."""
        key = names.canonical(key)
        if isinstance(value, dict):
            for sub_key, sub_value in value.items():
                self._unroll(names.join(key + "/", str(sub_key)), sub_value)
            return
        self.launch.params[key] = value

    def _rosparam(self, element: Element, context: _Context, *_: object, node: str | None = None) -> None:
        command = self._attr(element, context, "command") or "load"
        if command != "load":
            raise LaunchError(f"<rosparam command=\"{command}\"> runs rosparam at launch time, which the grader "
                              "does not do; only command=\"load\" (the default) is supported")
        base = names.global_ns(node) if node is not None else context.ns
        ns = self._attr(element, context, "ns")
        if ns:
            base = names.global_ns(names.join(base, ns))
        param = self._attr(element, context, "param")
        file_name = self._attr(element, context, "file")
        if file_name is not None:
            text = self._read_text(Path(file_name), "<rosparam file=...>")
        else:
            text = element.text
        if self._flag(element, context, "subst_value"):
            text = self._sub(text, context)
        try:
            data = load_yaml(text)
        except ValueTooLarge as exc:
            raise LaunchError(f"<rosparam>: {exc}") from None
        except yaml.YAMLError as exc:
            mark = getattr(exc, "problem_mark", None)
            at = f" (YAML line {mark.line + 1})" if mark is not None else ""
            raise LaunchError(f"<rosparam> holds invalid YAML{at}: {getattr(exc, 'problem', None) or exc}") from None
        if data is None:
            data = {}
        if param:
            self._unroll(names.join(base, param), data)
        elif isinstance(data, dict):
            self._unroll(base, data)
        else:
            raise LaunchError("<rosparam> with a value that is not a dictionary needs a param= attribute")

    def _node(self, element: Element, context: _Context, *_: object) -> None:
        for refused in ("machine", "launch-prefix"):
            if refused in element.attrs:
                raise LaunchError(f"<node {refused}=...> is not supported by the grader: remove it "
                                  "(nodes run on one machine, directly)")
        pkg = self._attr(element, context, "pkg", required=True)
        node_type = self._attr(element, context, "type", required=True)
        name = self._attr(element, context, "name", required=True)
        if not name or "/" in name:
            raise LaunchError(f"node name \"{name}\" must be a plain name without '/': use ns= for a namespace")
        output = self._attr(element, context, "output") or "log"
        if output not in ("log", "screen"):
            raise LaunchError(f"output=\"{output}\" on node {name}: expected log or screen")
        required, respawn = self._flag(element, context, "required"), self._flag(element, context, "respawn")
        if required and respawn:
            raise LaunchError(f"node {name} has both required=\"true\" and respawn=\"true\"; use one")
        namespace = names.global_ns(names.join(context.ns, self._attr(element, context, "ns") or ""))
        full = namespace + name
        for key, value in context.private_params.items():
            self.launch.params[names.canonical(names.join(full + "/", key))] = value
        remaps = list(context.remaps)
        for child in element.children:
            if not self._active(child, context):
                continue
            if child.tag == "param":
                self._param(child, context, node=full)
            elif child.tag == "rosparam":
                self._rosparam(child, context, node=full)
            elif child.tag == "remap":
                _add_remap(remaps, self._remap_pair(child, context))
            elif child.tag == "env":
                self._env(child, context)
            else:
                self.launch.notes.append(f"{Where(context.file, child.line)}: <{child.tag}> inside <node> is not "
                                         "a roslaunch tag; it was ignored")
        try:
            args = tuple(shlex.split(self._attr(element, context, "args") or ""))
        except ValueError as exc:
            raise LaunchError(f"args= of node {name} cannot be split into words: {exc}") from None
        self.launch.nodes.append(LaunchNode(
            pkg=pkg, type=node_type, name=name, namespace=namespace, args=args, remaps=tuple(remaps), output=output,
            required=required, respawn=respawn, where=Where(context.file, element.line)))

    def _include(self, element: Element, context: _Context, passed: dict[str, str], declared: set[str]) -> None:
        where = Where(context.file, element.line)
        file_name = self._attr(element, context, "file", required=True)
        child = context.child(self._attr(element, context, "ns"), fresh_args=True)
        given: dict[str, str] = {}
        if self._flag(element, context, "pass_all_args"):
            given = {k: v for k, v in context.args.items() if v is not None}
        explicit: list[str] = []
        for arg in element.children:
            if arg.tag != "arg" or not self._active(arg, context):
                continue
            name = self._attr(arg, context, "name", required=True)
            value = self._attr(arg, context, "value") if "value" in arg.attrs else self._attr(arg, context, "default")
            if value is None:
                raise LaunchError(f"<arg name=\"{name}\"> inside <include> needs value=")
            given[name] = value
            explicit.append(name)
        try:
            world = known.world_file(file_name)
        except known.UnknownPackage as exc:
            raise LaunchError(str(exc)) from None
        if world is not None:
            self._world(world, given, explicit, where)
            return
        path = Path(file_name)
        if not path.is_absolute():
            path = context.file.parent / path
        if self.depth >= MAX_INCLUDE_DEPTH:
            raise LaunchError(f"includes nest deeper than {MAX_INCLUDE_DEPTH} files (does a file include itself?)")
        self.files_read += 1
        if self.files_read > MAX_FILES:
            raise LaunchError(f"the launch file includes more than {MAX_FILES} files in all; the grader stops there")
        if self.confine_to is not None and not path.resolve().is_relative_to(self.confine_to):
            raise LaunchError(f"<include> of {path}, which is outside your submission: include your own launch "
                              "files with $(find your_package)/launch/...")
        root = self._parse(path.resolve(), where)
        self.depth += 1
        try:
            file_declared = self._scope_file(root, replace(child, file=path.resolve()), given)
        finally:
            self.depth -= 1
        unused = [name for name in explicit if name not in file_declared]
        if unused:
            raise LaunchError(f"unused args [{', '.join(unused)}] for include of [{path}]")

    def _world(self, world: tuple[str, str, known.WorldFile], given: dict[str, str], explicit: list[str],
               where: Where) -> None:
        package, inside, description = world
        unused = [name for name in explicit if name not in description.args]
        if unused:
            raise LaunchError(f"unused args [{', '.join(unused)}] for include of [{package}/{inside}]")
        scope_context = _Context(where.file, "/", {})
        try:
            values = {name: given[name] if name in given else self._sub(default, scope_context)
                      for name, default in description.args.items()}
        except SubstitutionError:
            raise LaunchError(f"{package}/{inside} takes its model from $TURTLEBOT3_MODEL, which is not set: export "
                              "TURTLEBOT3_MODEL=waffle as the course's ~/.bashrc does, or pass <arg name=\"model\" "
                              "value=\"waffle\"/> in the <include>") from None
        try:
            robot = known.robot_for(description, values)
            x, y = float(values[description.x_arg]), float(values[description.y_arg])
            yaw = float(values[description.yaw_arg]) if description.yaw_arg else 0.0
        except known.UnknownPackage as exc:
            raise LaunchError(str(exc)) from None
        except ValueError as exc:
            raise LaunchError(f"the spawn pose of {package}/{inside} is not a number: {exc}") from None
        self.launch.worlds.append(WorldLaunch(package=package, file=inside, robot=robot, x=x, y=y, yaw=yaw,
                                              where=where))


def _add_remap(remaps: list[tuple[str, str]], pair: tuple[str, str]) -> None:
    """A later remap of the same name replaces the earlier one, as in roslaunch."""
    remaps[:] = [r for r in remaps if r[0] != pair[0]]
    remaps.append(pair)


def read_launch(path: Path, args: Mapping[str, str] | None = None, packages: Mapping[str, Path] | None = None,
                env: Mapping[str, str] | None = None, confine_to: Path | None = None) -> Launch:
    """Read the launch file at ``path`` with ``name:=value`` args; LaunchError says what is wrong and where.

    ``confine_to``: the files it includes or loads must be inside this folder (a submission being graded must not
    read the grader's machine); None reads any file, as roslaunch does.
    """
    env = known.DEFAULT_ENV if env is None else env
    return Reader(packages or {}, env, confine_to).read(Path(path), args or {})
