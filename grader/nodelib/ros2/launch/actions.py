"""The actions of ROS 2 launch: arguments, groups, includes, timers, processes, event handlers, logging."""
from __future__ import annotations

import os
from typing import Any, Callable, Optional

from launch.core import (
    Action, ExternalLaunchDescription, LaunchContext, LaunchDescriptionEntity, Substitution, TextSubstitution,
    normalize_to_list_of_substitutions, perform_substitutions,
)

__all__ = ["AppendEnvironmentVariable", "DeclareLaunchArgument", "EmitEvent", "ExecuteProcess", "GroupAction", "IncludeLaunchDescription",
           "LogInfo", "OpaqueFunction", "PopEnvironment", "PopLaunchConfigurations", "PushEnvironment",
           "PushLaunchConfigurations", "RegisterEventHandler", "ResetLaunchConfigurations", "SetEnvironmentVariable",
           "SetLaunchConfiguration", "Shutdown", "TimerAction", "UnsetEnvironmentVariable", "UnsetLaunchConfiguration"]


class DeclareLaunchArgument(Action):
    """An argument the launch file accepts: its default, description and allowed values."""

    def __init__(self, name: str, *, default_value: Any = None, description: str | None = None,
                 choices: list[str] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = name
        self.default_value = None if default_value is None else normalize_to_list_of_substitutions(default_value)
        self.choices = choices
        if choices is not None and len(choices) == 0:
            raise RuntimeError("Provided choices arg is empty. Use None to ignore the choice list.")
        if choices is not None and default_value is not None and not isinstance(default_value, (Substitution, list)) \
                and default_value not in choices:
            raise RuntimeError(f'Provided default_value "{default_value}" is not in provided choices "{choices}".')
        if description is None:
            description = "no description given" if choices is None else "One of: " + str(choices)
        elif choices is not None:
            description = (description if description.endswith(".") else description + ".") \
                + " Valid choices are: " + str(choices)
        self.description = description
        self._conditionally_included = False

    def execute(self, context: LaunchContext) -> None:
        if self.name not in context.launch_configurations:
            if self.default_value is None:
                raise RuntimeError(f'Required launch argument "{self.name}" was not provided.')
            context.launch_configurations[self.name] = perform_substitutions(context, self.default_value)
        if self.choices is not None:
            value = context.launch_configurations[self.name]
            if value not in self.choices:
                raise RuntimeError(f'Argument "{self.name}" provided value "{value}" is not valid. Valid options '
                                   f"are: {self.choices}")
        context.recorder.declared(self, context)
        return None


class SetLaunchConfiguration(Action):
    """Sets a launch configuration in the current scope."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations[perform_substitutions(context, self.name)] = \
            perform_substitutions(context, self.value)


class UnsetLaunchConfiguration(Action):
    """Removes a launch configuration from the current scope."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations.pop(perform_substitutions(context, self.name), None)


class PushLaunchConfigurations(Action):
    """Saves the launch configurations (a scoped group's start)."""

    def execute(self, context: LaunchContext) -> None:
        context.push_launch_configurations()


class PopLaunchConfigurations(Action):
    """Restores the saved launch configurations (a scoped group's end)."""

    def execute(self, context: LaunchContext) -> None:
        context.pop_launch_configurations()


class PushEnvironment(Action):
    """Saves the environment."""

    def execute(self, context: LaunchContext) -> None:
        context.push_environment()


class PopEnvironment(Action):
    """Restores the saved environment."""

    def execute(self, context: LaunchContext) -> None:
        context.pop_environment()


class SetEnvironmentVariable(Action):
    """Sets an environment variable for what the launch starts after it."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)

    def execute(self, context: LaunchContext) -> None:
        context.environment[perform_substitutions(context, self.name)] = perform_substitutions(context, self.value)


class UnsetEnvironmentVariable(Action):
    """Removes an environment variable for what the launch starts after it."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)

    def execute(self, context: LaunchContext) -> None:
        context.environment.pop(perform_substitutions(context, self.name), None)


class AppendEnvironmentVariable(Action):
    """Appends (or prepends) a value to an environment variable, with the path separator."""

    def __init__(self, name: Any, value: Any, *, prepend: Any = False, separator: Any = os.pathsep,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)
        self.prepend = prepend
        self.separator = normalize_to_list_of_substitutions(separator)

    def execute(self, context: LaunchContext) -> None:
        name = perform_substitutions(context, self.name)
        value = perform_substitutions(context, self.value)
        separator = perform_substitutions(context, self.separator)
        prepend = self.prepend if isinstance(self.prepend, bool) else \
            perform_substitutions(context, normalize_to_list_of_substitutions(self.prepend)).lower() in ("true", "1")
        old = context.environment.get(name)
        context.environment[name] = value if not old else (value + separator + old if prepend
                                                           else old + separator + value)


class GroupAction(Action):
    """Actions together; scoped (default) keeps their launch configurations and ROS namespace inside."""

    def __init__(self, actions: list[Action], *, scoped: bool = True, forwarding: bool = True,
                 launch_configurations: dict[Any, Any] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.actions = list(actions)
        self.scoped = scoped
        self.forwarding = forwarding
        self.launch_configurations = dict(launch_configurations or {})

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        sets: list[LaunchDescriptionEntity] = [SetLaunchConfiguration(k, v)
                                               for k, v in self.launch_configurations.items()]
        if not self.scoped:
            return [*sets, *self.actions]
        if self.forwarding:
            return [PushLaunchConfigurations(), PushEnvironment(), *sets, *self.actions, PopEnvironment(),
                    PopLaunchConfigurations()]
        return [PushLaunchConfigurations(), PushEnvironment(), ResetLaunchConfigurations(self.launch_configurations),
                *self.actions, PopEnvironment(), PopLaunchConfigurations()]

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        return self.get_sub_entities()


class ResetLaunchConfigurations(Action):
    """Clears the launch configurations but for the ones given (a non-forwarding group)."""

    def __init__(self, launch_configurations: dict[Any, Any] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.keep = dict(launch_configurations or {})

    def execute(self, context: LaunchContext) -> None:
        kept = {perform_substitutions(context, normalize_to_list_of_substitutions(k)):
                perform_substitutions(context, normalize_to_list_of_substitutions(v)) for k, v in self.keep.items()}
        context.launch_configurations.clear()
        context.launch_configurations.update(kept)


class IncludeLaunchDescription(Action):
    """Another launch file (Python, XML or YAML), with launch arguments set for it (not scoped, as in Jazzy)."""

    def __init__(self, launch_description_source: Any, *, launch_arguments: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        from launch.launch_description_sources import AnyLaunchDescriptionSource, LaunchDescriptionSource
        if not isinstance(launch_description_source, LaunchDescriptionSource):
            launch_description_source = AnyLaunchDescriptionSource(launch_description_source)
        self.launch_description_source = launch_description_source
        items = launch_arguments.items() if hasattr(launch_arguments, "items") else (launch_arguments or [])
        self.launch_arguments = [(normalize_to_list_of_substitutions(k), normalize_to_list_of_substitutions(v))
                                 for k, v in items]

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        description = self.launch_description_source.get_launch_description(context)
        path = self.launch_description_source.location
        context.extend_locals({"current_launch_file_path": path,
                               "current_launch_file_directory": os.path.dirname(path)})
        given = [perform_substitutions(context, k) for k, _ in self.launch_arguments]
        for argument, includes in description.get_launch_arguments_with_include_launch_description_actions():
            if argument._conditionally_included or argument.default_value is not None:
                continue
            for include in includes or []:
                given.extend(include.argument_names_without_context())
            if argument.name not in given:
                raise RuntimeError(f"Included launch description missing required argument '{argument.name}' "
                                   f"(description: '{argument.description}'), given: [{', '.join(given)}]")
        sets = [SetLaunchConfiguration(k, v) for k, v in self.launch_arguments]
        if isinstance(description, ExternalLaunchDescription):
            context.recorder.external_includes[-1]["arguments"] = {
                perform_substitutions(context, k): perform_substitutions(context, v) for k, v in self.launch_arguments}
            return sets
        return [*sets, description]

    def argument_names_without_context(self) -> list[str]:
        """The names of its launch arguments that need no context to be known."""
        names = []
        for key, _ in self.launch_arguments:
            try:
                names.append(perform_substitutions(LaunchContext(), key))
            except Exception:
                continue
        return names

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        description = self.launch_description_source.try_get_launch_description_without_context()
        return [description] if description is not None else []


class TimerAction(Action):
    """Actions started after a delay (recorded with the delay; launch's timers run in sim time under rosgrade)."""

    def __init__(self, *, period: Any, actions: list[LaunchDescriptionEntity], cancel_on_shutdown: Any = True,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.period = period if isinstance(period, (int, float)) else normalize_to_list_of_substitutions(period)
        self.actions = list(actions)

    def execute(self, context: LaunchContext) -> None:
        period = self.period if isinstance(self.period, (int, float)) \
            else float(perform_substitutions(context, self.period))
        context.recorder.defer(float(period), self.actions, context)

    def describe_conditional_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.actions


class ExecuteProcess(Action):
    """A program to start: its command line, whether through a shell, its name, where its output goes."""

    def __init__(self, *, cmd: Any, name: Any = None, cwd: Any = None, env: Any = None, additional_env: Any = None,
                 shell: bool = False, output: Any = "log", emulate_tty: bool = False, sigterm_timeout: Any = 5,
                 sigkill_timeout: Any = 5, prefix: Any = None, respawn: Any = False, respawn_delay: Any = None,
                 respawn_max_retries: int = -1, on_exit: Any = None, log_cmd: bool = False,
                 cached_output: bool = False, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.cmd = [normalize_to_list_of_substitutions(item) for item in cmd]
        self.process_name = None if name is None else normalize_to_list_of_substitutions(name)
        self.cwd = None if cwd is None else normalize_to_list_of_substitutions(cwd)
        self.additional_env = [(normalize_to_list_of_substitutions(k), normalize_to_list_of_substitutions(v))
                               for k, v in (additional_env or {}).items()]
        self.shell = shell
        self.output = normalize_to_list_of_substitutions(output)
        self.on_exit = on_exit

    def _name(self, context: LaunchContext, argv: list[str]) -> str:
        if self.process_name is not None:
            return perform_substitutions(context, self.process_name)
        return os.path.basename(argv[0]) if argv else ""

    def describe_process(self, context: LaunchContext) -> dict[str, Any]:
        argv = [perform_substitutions(context, item) for item in self.cmd]
        return {"kind": "process", "cmd": argv, "shell": self.shell, "name": self._name(context, argv),
                "output": perform_substitutions(context, self.output),
                "cwd": None if self.cwd is None else perform_substitutions(context, self.cwd),
                "env": {perform_substitutions(context, k): perform_substitutions(context, v)
                        for k, v in self.additional_env}}

    def execute(self, context: LaunchContext) -> None:
        context.recorder.process(self, self.describe_process(context), context)


class RegisterEventHandler(Action):
    """Registers a handler (OnProcessStart, OnProcessExit, OnShutdown) whose actions run on its event."""

    def __init__(self, event_handler: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event_handler = event_handler

    def execute(self, context: LaunchContext) -> None:
        context.recorder.register(self.event_handler, context)

    def describe_conditional_sub_entities(self) -> list[LaunchDescriptionEntity]:
        handler = self.event_handler.handler
        return list(handler) if isinstance(handler, (list, tuple)) else []


class LogInfo(Action):
    """A message launch logs."""

    def __init__(self, *, msg: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.msg = normalize_to_list_of_substitutions(msg)

    def execute(self, context: LaunchContext) -> None:
        context.recorder.log(perform_substitutions(context, self.msg), context)


class OpaqueFunction(Action):
    """A Python function called with the context, which may return more actions."""

    def __init__(self, *, function: Callable[..., Any], args: Any = None, kwargs: Any = None, **left: Any) -> None:
        super().__init__(**left)
        self.function = function
        self.args = list(args or [])
        self.kwargs = dict(kwargs or {})

    def execute(self, context: LaunchContext) -> Optional[list[LaunchDescriptionEntity]]:
        return self.function(context, *self.args, **self.kwargs)


class EmitEvent(Action):
    """Emits an event: a Shutdown event ends the launch."""

    def __init__(self, *, event: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event = event

    def execute(self, context: LaunchContext) -> None:
        context.recorder.event(self.event, context)


class Shutdown(EmitEvent):
    """Ends the launch (and every process it started)."""

    def __init__(self, *, reason: Any = "reason not given", **kwargs: Any) -> None:
        from launch.events import Shutdown as ShutdownEvent
        super().__init__(event=ShutdownEvent(reason=reason), **kwargs)
