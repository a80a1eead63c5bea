"""ROS actions of launch_ros: Node (and the argv launch_ros builds for it), PushRosNamespace, SetRemap,
SetParameter."""
from __future__ import annotations

import os
from typing import Any

from launch.actions import ExecuteProcess
from launch.core import Action, LaunchContext, SubstitutionFailure, normalize_to_list_of_substitutions, \
    perform_substitutions
from launch_ros import params
from launch_ros.parameter_descriptions import Parameter, ParameterFile
from launch_ros.substitutions import ExecutableInPackage
from rclpy.exceptions import InvalidNamespaceException
from rclpy.names import validate_namespace, validate_node_name
from ament_index_python.packages import index

__all__ = ["Node", "PushROSNamespace", "PushRosNamespace", "SetParameter", "SetParametersFromFile", "SetRemap"]

UNSPECIFIED_NAME = "<node_name_unspecified>"
UNSPECIFIED_NAMESPACE = "<node_namespace_unspecified>"


def prefix_namespace(base: str | None, ns: str | None) -> str | None:
    """ns under base when ns is relative; trailing '/' stripped (as launch_ros does)."""
    if base is None and ns is None:
        return None
    if ns is None:
        result = base
    elif base is None or ns.startswith("/"):
        result = ns
    else:
        result = base.rstrip("/") + "/" + ns
    return result if result == "/" else result.rstrip("/") or "/"


def absolute(ns: str | None) -> str | None:
    return None if ns is None else ns if ns.startswith("/") else "/" + ns


class Node(ExecuteProcess):
    """A ROS node of a package: launch_ros turns its name, namespace, parameters and remappings into argv."""

    def __init__(self, *, executable: Any, package: Any = None, name: Any = None, namespace: Any = None,
                 exec_name: Any = None, parameters: Any = None, remappings: Any = None, ros_arguments: Any = None,
                 arguments: Any = None, **kwargs: Any) -> None:
        kwargs.setdefault("output", "log")
        super().__init__(cmd=[executable], name=exec_name, **kwargs)
        self.package = None if package is None else normalize_to_list_of_substitutions(package)
        self.executable = normalize_to_list_of_substitutions(executable)
        self.node_name = None if name is None else normalize_to_list_of_substitutions(name)
        self.node_namespace = None if namespace is None else normalize_to_list_of_substitutions(namespace)
        self.parameters = None if parameters is None else params.normalize(parameters)
        self.remappings = [(normalize_to_list_of_substitutions(a), normalize_to_list_of_substitutions(b))
                           for a, b in (remappings or [])]
        self.arguments = [normalize_to_list_of_substitutions(a) for a in (arguments or [])]
        self.ros_arguments = None if ros_arguments is None else [normalize_to_list_of_substitutions(a)
                                                                  for a in ros_arguments]

    def describe_process(self, context: LaunchContext) -> dict[str, Any]:
        executable = perform_substitutions(context, self.executable)
        package = None if self.package is None else perform_substitutions(context, self.package)
        path = executable if package is None else ExecutableInPackage(executable, package).perform(context)
        entry = index().get(package or "", {})
        if entry.get("external"):
            try:
                return self._described(context, package, executable, path, entry)
            except Exception:  # noqa: BLE001 - a node never run may need what the grader does not do (xacro)
                return self._external(context, package, executable, path)
        return self._described(context, package, executable, path, entry)

    def _described(self, context: LaunchContext, package: str | None, executable: str, path: str,
                   entry: dict[str, Any]) -> dict[str, Any]:
        """The node with the argv launch_ros builds: arguments, name, namespace, parameters, remappings."""
        args = [perform_substitutions(context, a) for a in self.arguments]
        if self.ros_arguments is not None:
            args += ["--ros-args", *(perform_substitutions(context, a) for a in self.ros_arguments)]
        args.append("--ros-args")
        name = None if self.node_name is None else perform_substitutions(context, self.node_name)
        if name is not None:
            validate_node_name(name)
            args += ["-r", f"__node:={name}"]
        ns = None if self.node_namespace is None else perform_substitutions(context, self.node_namespace)
        ns = absolute(prefix_namespace(context.launch_configurations.get("ros_namespace"), ns))
        if ns is not None:
            validate_namespace(ns)
            args += ["-r", f"__ns:={ns}"]
        full = prefix_namespace(ns or "", name or UNSPECIFIED_NAME) if ns is not None else (name or UNSPECIFIED_NAME)
        full_known = full if name is not None and ns is not None else None
        files: list[dict[str, Any]] = []
        for item in context.launch_configurations.get("global_params") or []:
            if isinstance(item, tuple):
                args += ["-p", f"{item[0]}:={item[1]}"]
            else:
                files.append(context.recorder.params_file(os.path.abspath(item), None))
                args += ["--params-file", files[-1]["path"]]
        for item in self.parameters or []:
            if isinstance(item, dict):
                values = params.evaluate_dict(context, item)
                files.append(context.recorder.params_file(None, params.params_file_content(full_known, values)))
            elif isinstance(item, ParameterFile):
                found = context.recorder.params_file(item.evaluate(context), None)
                if found is None:
                    continue
                files.append(found)
            elif isinstance(item, Parameter):
                pname, value = item.evaluate(context)
                args += ["-p", params.rule(pname, value)]
                continue
            args += ["--params-file", files[-1]["path"]]
        remaps = list(context.launch_configurations.get("ros_remaps") or [])
        remaps += [(perform_substitutions(context, a), perform_substitutions(context, b)) for a, b in self.remappings]
        for src, dst in remaps:
            args += ["-r", f"{src}:={dst}"]
        described = super().describe_process(context)
        process_name = described["name"] if self.process_name is not None else os.path.basename(path)
        return {**described, "kind": "node", "external": bool(entry.get("external")), "world": bool(entry.get("world")),
                "package": package, "executable": executable, "name": process_name,
                "node_name": name, "namespace": ns, "cmd": [path, *args], "args": args, "params_files": files}


    def _external(self, context: LaunchContext, package: str | None, executable: str, path: str) -> dict[str, Any]:
        """A node of a package rosgrade never runs (rviz2, Gazebo...): named, its parameters not evaluated (they may
        need programs the grader does not run, such as xacro)."""
        name = None if self.node_name is None else perform_substitutions(context, self.node_name)
        described = super().describe_process(context)
        return {**described, "kind": "node", "external": True, "world": False, "package": package,
                "executable": executable, "name": os.path.basename(path) if self.process_name is None
                else described["name"], "node_name": name, "namespace": None, "cmd": [path], "args": [],
                "params_files": [], "not_evaluated": "parameters, remappings and arguments (never run)"}


class PushRosNamespace(Action):
    """Puts the nodes after it (in its group) under a namespace."""

    def __init__(self, namespace: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.namespace = normalize_to_list_of_substitutions(namespace)

    def execute(self, context: LaunchContext) -> None:
        pushed = perform_substitutions(context, self.namespace)
        previous = context.launch_configurations.get("ros_namespace")
        namespace = absolute(prefix_namespace(previous, pushed))
        try:
            validate_namespace(namespace or "")
        except InvalidNamespaceException:
            raise SubstitutionFailure(f"The resulting namespace is invalid: [previous_namespace='{previous}', "
                                      f"pushed_namespace='{pushed}']") from None
        context.launch_configurations["ros_namespace"] = namespace


PushROSNamespace = PushRosNamespace


class SetRemap(Action):
    """A remapping for every node after it in its scope."""

    def __init__(self, src: Any, dst: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.src = normalize_to_list_of_substitutions(src)
        self.dst = normalize_to_list_of_substitutions(dst)

    def execute(self, context: LaunchContext) -> None:
        remaps = context.launch_configurations.get("ros_remaps", [])
        remaps.append((perform_substitutions(context, self.src), perform_substitutions(context, self.dst)))
        context.launch_configurations["ros_remaps"] = remaps


class SetParameter(Action):
    """A parameter for every node after it in its scope (-p before the node's own)."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.values = params.normalize_dict({name: value})

    def execute(self, context: LaunchContext) -> None:
        found = context.launch_configurations.get("global_params", [])
        found.extend(params.evaluate_dict(context, self.values).items())
        context.launch_configurations["global_params"] = found


class SetParametersFromFile(Action):
    """A parameter file for every node after it in its scope (--params-file before the node's own)."""

    def __init__(self, filename: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.filename = normalize_to_list_of_substitutions(filename)

    def execute(self, context: LaunchContext) -> None:
        found = context.launch_configurations.get("global_params", [])
        found.append(perform_substitutions(context, self.filename))
        context.launch_configurations["global_params"] = found
