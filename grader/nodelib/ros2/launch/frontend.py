"""XML and YAML launch files (launch_xml, launch_yaml) read into the same actions a Python launch file builds.

Both formats are a tree of entities: a tag (``node``, ``arg``, ``include``...) with attributes and children. XML
attributes are text; YAML values keep their YAML type. ``if``/``unless`` on any action are its condition.
"""
from __future__ import annotations

import os
import xml.etree.ElementTree as ElementTree
from typing import Any, Callable

import yaml

from launch import actions as a
from launch import conditions as c
from launch.core import Action, InvalidLaunchFileError, LaunchDescription, Substitution
from launch.frontend_substitutions import SubstitutionSyntaxError, is_plain, parse_substitution
from launch.launch_description_sources import AnyLaunchDescriptionSource

MAX_FILE_BYTES = 1 << 20


class Entity:
    """One tag of an XML or YAML launch file: its name, attributes and child entities."""

    def __init__(self, type_name: str, attrs: dict[str, Any], children: list["Entity"]) -> None:
        self.type_name = type_name
        self.attrs = attrs
        self.children = children

    def get(self, name: str, default: Any = None) -> Any:
        return self.attrs.get(name, default)

    def need(self, name: str) -> Any:
        if name not in self.attrs:
            raise AttributeError(f"Attribute '{name}' of type '<class 'str'>' not found in Entity '{self.type_name}'")
        return self.attrs[name]

    def list(self, name: str) -> list["Entity"]:
        """Child entities of one tag (XML: child elements; YAML: a list under that key)."""
        return [child for child in self.children if child.type_name == name]


def _xml_entity(element: ElementTree.Element) -> Entity:
    """An XML element; `name-sep="," name="a,b"` makes the attribute a list, as launch_xml reads it."""
    attrs: dict[str, Any] = {}
    for key, value in element.attrib.items():
        if key.endswith("-sep"):
            continue
        separator = element.attrib.get(f"{key}-sep")
        attrs[key] = value.split(separator) if separator is not None else value
    return Entity(element.tag, attrs, [_xml_entity(child) for child in element])


def _yaml_entity(type_name: str, body: Any) -> Entity:
    if not isinstance(body, dict):
        return Entity(type_name, {}, [])
    attrs: dict[str, Any] = {}
    children: list[Entity] = []
    for key, value in body.items():
        if key == "children" and isinstance(value, list):
            children += [_yaml_entity(*next(iter(item.items()))) for item in value if isinstance(item, dict) and item]
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            children += [_yaml_entity(key, item) for item in value]
        else:
            attrs[key] = value
    return Entity(type_name, attrs, children)


def read_entity(path: str) -> Entity:
    """The root `launch` entity of an XML or YAML launch file."""
    with open(path, encoding="utf-8") as handle:
        text = handle.read(MAX_FILE_BYTES)
    if text.lstrip().startswith("<"):
        try:
            root = _xml_entity(ElementTree.fromstring(text))
        except ElementTree.ParseError as exc:
            raise InvalidLaunchFileError(f"{os.path.basename(path)}: invalid XML: {exc}") from None
    else:
        try:
            data = yaml.safe_load(text)
        except yaml.YAMLError as exc:
            raise InvalidLaunchFileError(f"{os.path.basename(path)}: invalid YAML: {exc}") from None
        if not isinstance(data, dict) or "launch" not in data:
            raise InvalidLaunchFileError("The launch file may have a syntax error, or its format is unknown")
        items = data["launch"] or []
        root = Entity("launch", {}, [_yaml_entity(*next(iter(item.items()))) for item in items
                                     if isinstance(item, dict) and item])
    if root.type_name != "launch":
        raise InvalidLaunchFileError(f"{os.path.basename(path)}: the root tag is <{root.type_name}>, not <launch>")
    return root


def subs(value: Any) -> list[Substitution]:
    return parse_substitution("true" if value is True else "false" if value is False else value)


def _typed(value: Any) -> Any:
    """An attribute read with YAML rules (launch_xml's coercion): text with substitutions stays substitutions."""
    if isinstance(value, list):
        return [_typed(item) for item in value]
    if isinstance(value, str):
        loaded = yaml.safe_load(value) if value else value
        if not isinstance(loaded, str):
            if isinstance(loaded, (dict,)) or loaded is None:
                return value
            return loaded
        parts = parse_substitution(loaded)
        return loaded if is_plain(parts) else parts
    return value


def _cmdline(value: Any) -> list[list[Substitution]]:
    """A command line split on spaces, substitutions kept with the text beside them."""
    words: list[list[Substitution]] = []
    current: list[Substitution] = []
    from launch.core import TextSubstitution
    for part in subs(value):
        if not isinstance(part, TextSubstitution):
            current.append(part)
            continue
        pieces = part.text.split(" ")
        for index, piece in enumerate(pieces):
            if index > 0:
                if current:
                    words.append(current)
                current = []
            if piece:
                current.append(TextSubstitution(text=piece))
    if current:
        words.append(current)
    return words


def _condition(entity: Entity) -> dict[str, Any]:
    if "if" in entity.attrs:
        return {"condition": c.IfCondition(subs(entity.attrs["if"]))}
    if "unless" in entity.attrs:
        return {"condition": c.UnlessCondition(subs(entity.attrs["unless"]))}
    return {}


def _bool(value: Any) -> bool:
    return value if isinstance(value, bool) else str(value).strip().lower() in ("true", "1")


def _arg(entity: Entity) -> Action:
    choices = [str(choice.need("value")) for choice in entity.list("choice")] or None
    default = entity.get("default")
    return a.DeclareLaunchArgument(str(entity.need("name")),
                                   default_value=None if default is None else subs(default),
                                   description=entity.get("description"), choices=choices, **_condition(entity))


def _params(items: list[Entity]) -> list[Any]:
    from launch_ros.parameter_descriptions import ParameterFile, ParameterValue
    types: dict[str, Any] = {"str": str, "int": int, "float": float, "bool": bool}

    def nested(params: list[Entity]) -> dict[Any, Any]:
        found: dict[Any, Any] = {}
        for param in params:
            name = tuple(subs(param.need("name")))
            inner = param.list("param")
            if inner:
                found[name] = nested(inner)
                continue
            if "value" not in param.attrs:
                raise RuntimeError("either a value attribute or nested params are needed")
            kind = types.get(str(param.get("type"))) if param.get("type") is not None else None
            raw = param.attrs["value"]
            if kind is str and isinstance(raw, str):
                parts = parse_substitution(raw)
                value = raw if is_plain(parts) else parts
            else:
                value = _typed(raw)
            found[name] = ParameterValue(value, value_type=kind)
        return found

    out: list[Any] = []
    for param in items:
        if "from" in param.attrs:
            if "name" in param.attrs:
                raise RuntimeError("name and from attributes are mutually exclusive")
            out.append(ParameterFile(subs(param.attrs["from"])))
        elif "name" in param.attrs:
            out.append(nested([param]))
        else:
            raise ValueError("param Entity should have name or from attribute")
    return out


def _node(entity: Entity) -> Action:
    from launch_ros.actions import Node
    kwargs: dict[str, Any] = {"executable": subs(entity.need("exec")), **_condition(entity)}
    for attr, key in (("pkg", "package"), ("name", "name"), ("namespace", "namespace"), ("exec_name", "exec_name"),
                      ("output", "output")):
        if attr in entity.attrs:
            kwargs[key] = subs(entity.attrs[attr])
    if "args" in entity.attrs:
        kwargs["arguments"] = _cmdline(entity.attrs["args"])
    if "ros_args" in entity.attrs:
        kwargs["ros_arguments"] = _cmdline(entity.attrs["ros_args"])
    remaps = entity.list("remap")
    if remaps:
        kwargs["remappings"] = [(subs(r.need("from")), subs(r.need("to"))) for r in remaps]
    params = entity.list("param")
    if params:
        kwargs["parameters"] = _params(params)
    return Node(**kwargs)


def _executable(entity: Entity) -> Action:
    env = {tuple(subs(e.need("name"))): subs(e.need("value")) for e in entity.list("env")}
    kwargs: dict[str, Any] = {"cmd": _cmdline(entity.need("cmd")), "shell": _bool(entity.get("shell", False)),
                              **_condition(entity)}
    for attr, key in (("name", "name"), ("cwd", "cwd"), ("output", "output")):
        if attr in entity.attrs:
            kwargs[key] = subs(entity.attrs[attr])
    return a.ExecuteProcess(additional_env=env or None, **kwargs)


def _include(entity: Entity) -> Action:
    arguments = [(subs(arg.need("name")), subs(arg.need("value"))) for arg in entity.list("arg")]
    return a.IncludeLaunchDescription(AnyLaunchDescriptionSource(subs(entity.need("file"))),
                                      launch_arguments=arguments, **_condition(entity))


def _group(entity: Entity) -> Action:
    keep = {tuple(subs(k.need("name"))): subs(k.need("value")) for k in entity.list("keep")}
    return a.GroupAction([parse_action(child) for child in entity.children if child.type_name != "keep"],
                         scoped=_bool(entity.get("scoped", True)), forwarding=_bool(entity.get("forwarding", True)),
                         launch_configurations=keep or None, **_condition(entity))


def _ros(name: str) -> Callable[[Entity], Action]:
    def build(entity: Entity) -> Action:
        from launch_ros import actions as r
        if name == "push":
            return r.PushRosNamespace(subs(entity.need("namespace")), **_condition(entity))
        if name == "remap":
            return r.SetRemap(subs(entity.need("from")), subs(entity.need("to")), **_condition(entity))
        return r.SetParameter(subs(entity.need("name")), _typed(entity.need("value")), **_condition(entity))
    return build


BUILDERS: dict[str, Callable[[Entity], Action]] = {
    "arg": _arg,
    "let": lambda e: a.SetLaunchConfiguration(subs(e.need("name")), subs(e.need("value")), **_condition(e)),
    "node": _node,
    "executable": _executable,
    "include": _include,
    "group": _group,
    "timer": lambda e: a.TimerAction(period=subs(e.need("period")), actions=[parse_action(x) for x in e.children],
                                     **_condition(e)),
    "log": lambda e: a.LogInfo(msg=subs(e.need("message")), **_condition(e)),
    "set_env": lambda e: a.SetEnvironmentVariable(subs(e.need("name")), subs(e.need("value")), **_condition(e)),
    "set-env": lambda e: a.SetEnvironmentVariable(subs(e.need("name")), subs(e.need("value")), **_condition(e)),
    "push-ros-namespace": _ros("push"),
    "push_ros_namespace": _ros("push"),
    "set_remap": _ros("remap"),
    "set-remap": _ros("remap"),
    "set_parameter": _ros("param"),
    "set-parameter": _ros("param"),
    "shutdown": lambda e: a.Shutdown(reason=subs(e.get("reason", "reason not given")), **_condition(e)),
}


def parse_action(entity: Entity) -> Action:
    builder = BUILDERS.get(entity.type_name)
    if builder is None:
        raise RuntimeError(f"Unrecognized entity of the type: {entity.type_name}")
    try:
        return builder(entity)
    except SubstitutionSyntaxError as exc:
        raise InvalidLaunchFileError(f"<{entity.type_name}>: {exc}") from None


def load_frontend(path: str) -> LaunchDescription:
    """The launch description of an XML or YAML launch file."""
    root = read_entity(path)
    return LaunchDescription([parse_action(child) for child in root.children])
