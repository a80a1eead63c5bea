"""The `ros2` command lines a launch file's ExecuteProcess runs (`ros2 service call`, `ros2 param set`,
`ros2 topic pub`, `ros2 action send_goal`, as the ROS 2 launch tutorials run them against turtlesim), carried out by
the grader as the scenario's own acts at the time launch would run them: the grader is the caller, as the CLI is a
node of its own. Other programs are not run."""
from __future__ import annotations

import os
import shlex
from dataclasses import dataclass, field
from typing import Any

import yaml
from pydantic import ValidationError

from grader.launch.turtlesim import first_window, is_world
from grader.nodelib.common.rosgrade_param_files import ParamFileError, ParamSet
from sim.scenario import ActionGoalSpec, ParamSetSpec, PublicationSpec, Scenario, ServiceCallSpec, TurtlesimWindow

_TOPIC_PUB_FLAGS = {"-r": "rate", "--rate": "rate", "-t": "times", "--times": "times"}
# ros2 topic pub options that take a value rosgrade does not model (QoS, waiting, printing)
_TOPIC_PUB_IGNORED = {"-p", "--print", "-w", "--wait-matching-subscriptions", "--keep-alive", "--qos-profile",
                      "--qos-depth", "--qos-history", "--qos-reliability", "--qos-durability", "--node-name", "-n"}


class ActError(Exception):
    """A ros2 command line rosgrade cannot carry out as written."""


@dataclass
class LaunchActs:
    """What the grader does for the launch file's ros2 command lines, by kind, in launch's start order."""

    service_calls: list[ServiceCallSpec] = field(default_factory=list)
    param_sets: list[ParamSetSpec] = field(default_factory=list)
    publications: list[PublicationSpec] = field(default_factory=list)
    action_goals: list[ActionGoalSpec] = field(default_factory=list)
    # The parameters the launch file starts the world's node with (turtlesim_node's `parameters=`), by name.
    world_params: dict[str, Any] = field(default_factory=dict)
    # Its further turtlesim_nodes: windows of their own (the launch tutorial's turtlesim_mimic_launch.py)
    turtlesim_windows: list[TurtlesimWindow] = field(default_factory=list)
    # The launched turtlesim's names (and node name) that lead to the world's, which every act addressing them takes
    world_names: dict[str, str] = field(default_factory=dict)

    def add(self, act: Any) -> None:
        kind = {ServiceCallSpec: self.service_calls, ParamSetSpec: self.param_sets,
                PublicationSpec: self.publications, ActionGoalSpec: self.action_goals}[type(act)]
        kind.append(act)

    def __bool__(self) -> bool:
        return bool(self.service_calls or self.param_sets or self.publications or self.action_goals
                    or self.world_params or self.turtlesim_windows or self.world_names)


def _words(process: dict[str, Any]) -> list[str]:
    if process.get("shell"):
        try:
            return shlex.split(" ".join(process["cmd"]))
        except ValueError as exc:
            raise ActError(f"its command line does not parse as a shell's would ({exc})") from None
    return list(process["cmd"])


def _absolute(name: str) -> str:
    return name if name.startswith("/") else "/" + name


def _yaml(text: str | None, what: str) -> Any:
    if text is None:
        return {}
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError:
        raise ActError(f"its {what} {text!r} is not YAML, as the ros2 command line reads it") from None


def _positional(words: list[str], flags_with_value: set[str]) -> tuple[list[str], dict[str, str], set[str]]:
    """The command's positional words, its options with a value, and its bare flags."""
    positional, options, flags = [], {}, set()
    index = 0
    while index < len(words):
        word = words[index]
        if word in flags_with_value and index + 1 < len(words):
            options[word] = words[index + 1]
            index += 2
            continue
        if word.startswith("-") and not word.lstrip("-").replace(".", "").isdigit():
            flags.add(word)
        else:
            positional.append(word)
        index += 1
    return positional, options, flags


def cli_act(process: dict[str, Any], t: float) -> Any | None:
    """The scenario act for one of the launch file's processes (None: not a ros2 command rosgrade carries out)."""
    words = _words(process)
    if len(words) < 3 or os.path.basename(words[0]) != "ros2":  # `ros2` or its path (FindExecutable(name='ros2'))
        return None
    verb = tuple(words[1:3])
    rest = words[3:]
    if verb == ("service", "call"):
        positional, _, _ = _positional(rest, {"-r", "--rate"})
        if len(positional) < 2:
            raise ActError("`ros2 service call` needs a service name and its type")
        request = _yaml(positional[2] if len(positional) > 2 else None, "request")
        return ServiceCallSpec(t=t, service=_absolute(positional[0]), type=positional[1], request=request or {})
    if verb == ("param", "set"):
        positional, _, _ = _positional(rest, set())
        if len(positional) < 3:
            raise ActError("`ros2 param set` needs a node, a parameter name and a value")
        return ParamSetSpec(t=t, node=_absolute(positional[0]), name=positional[1],
                            value=_yaml(positional[2], "value"))
    if verb == ("topic", "pub"):
        positional, options, flags = _positional(rest, set(_TOPIC_PUB_FLAGS) | _TOPIC_PUB_IGNORED)
        if len(positional) < 2:
            raise ActError("`ros2 topic pub` needs a topic and its type")
        settings: dict[str, Any] = {_TOPIC_PUB_FLAGS[k]: float(v) if _TOPIC_PUB_FLAGS[k] == "rate" else int(v)
                                    for k, v in options.items() if k in _TOPIC_PUB_FLAGS}
        values = _yaml(positional[2] if len(positional) > 2 else None, "message")
        return PublicationSpec(t=t, topic=_absolute(positional[0]), type=positional[1], values=values or {},
                               once=bool(flags & {"-1", "--once"}), **settings)
    if verb == ("action", "send_goal"):
        positional, _, _ = _positional(rest, set())
        if len(positional) < 2:
            raise ActError("`ros2 action send_goal` needs an action name and its type")
        goal = _yaml(positional[2] if len(positional) > 2 else None, "goal")
        return ActionGoalSpec(t=t, action=_absolute(positional[0]), type=positional[1], goal=goal or {})
    return None


def launch_acts(processes: list[dict[str, Any]], file_name: str) -> tuple[LaunchActs, list[str], set[int]]:
    """The acts for the launch file's ros2 command lines, findings for those that cannot be carried out, and the
    indexes of the processes they stand for."""
    acts = LaunchActs()
    findings: list[str] = []
    handled: set[int] = set()
    first = first_window(processes)
    for index, process in enumerate(processes):
        if is_world(process):  # the first turtlesim_node's parameters; other windows' are their own
            if process is not first:
                continue
            try:
                acts.world_params.update(world_params(process))
            except ParamFileError as exc:
                findings.append(f"{file_name} gives {process['executable']} parameters rcl refuses: {exc.problem}.")
            continue
        if process["kind"] != "process":
            continue
        command = " ".join(process["cmd"])
        try:
            act = cli_act(process, float(process.get("delay") or 0.0))
        except (ActError, ValidationError, TypeError, ValueError) as exc:
            reason = exc.errors()[0]["msg"] if isinstance(exc, ValidationError) else str(exc)
            findings.append(f"{file_name} runs `{command}`, which rosgrade could not carry out: {reason}.")
            handled.add(index)
            continue
        if act is None:
            continue
        handled.add(index)
        acts.add(act)
        after = process.get("after")
        if after and after.get("process"):
            findings.append(f"{file_name}: `{command}` runs when {after['process']} "
                            f"{'exits' if after['event'] == 'exit' else 'starts'}; rosgrade carries it out at "
                            f"{act.t:g} s, in launch's order.")
    return acts, findings, handled


def world_params(process: dict[str, Any]) -> dict[str, Any]:
    """The parameters a world node (turtlesim_node) gets from its launch description, as rcl reads its command line:
    each --params-file (launch_ros's, by content) and -p, in order, for the node's full name."""
    overrides = ParamSet()
    contents = iter(process.get("params_files", []))
    args = process.get("args", [])
    for flag, value in zip(args, args[1:]):
        if flag == "--params-file":
            overrides.read_text(str(next(contents)["content"]))
        elif flag in ("-p", "--param"):
            name, _, text = value.partition(":=")
            node, _, name = name.rpartition(":")
            overrides.set_value(node or "/**", name, text)
    namespace = process.get("namespace") or ""
    full_name = f"{namespace.rstrip('/')}/{process.get('node_name') or process['executable']}"
    return {name: value for name, value in overrides.for_node(full_name).items() if value is not None}


_ADDRESS = {ServiceCallSpec: "service", ParamSetSpec: "node", PublicationSpec: "topic", ActionGoalSpec: "action"}
KINDS = ("service_calls", "param_sets", "publications", "action_goals")


def renamed(acts: list[Any], names: dict[str, str]) -> list[Any]:
    """The acts with the name each addresses (its service, node, topic or action) led through ``names``."""
    out = []
    for act in acts:
        address = _ADDRESS[type(act)]
        name = getattr(act, address)
        out.append(act.model_copy(update={address: names[name]}) if name in names else act)
    return out


def with_acts(scenario: Scenario, acts: LaunchActs) -> Scenario:
    """The scenario with the launch file's acts added to its own, each list in time order, every act addressing the
    launched turtlesim led to the world, and the world's node started with the launch file's parameters for it."""
    if not acts:
        return scenario
    update: dict[str, Any] = {
        name: sorted(renamed([*getattr(scenario, name), *getattr(acts, name)], acts.world_names), key=lambda a: a.t)
        for name in KINDS if getattr(acts, name) or acts.world_names}
    if acts.world_params:
        update["world_params"] = {**scenario.world_params, **acts.world_params}
    if acts.turtlesim_windows:
        update["turtlesim_windows"] = [*scenario.turtlesim_windows, *acts.turtlesim_windows]
    return scenario.model_copy(update=update)
