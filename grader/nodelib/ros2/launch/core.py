"""The launch core a launch file builds on: substitutions, actions, conditions, the context and the description.

Written for rosgrade from the documented behaviour of ROS 2 Jazzy's ``launch``: a launch file's entities are visited
depth first, each action's ``execute`` returning the entities to visit next, and substitutions are performed against
the context's launch configurations, which groups push and pop. Processes are not started: they are recorded, in the
order launch would start them, by the evaluator (``launch.rosgrade_evaluate``).
"""
from __future__ import annotations

import os
from collections.abc import Iterable
from typing import Any, Callable, Optional, Union


# The evaluator's recorder, for contexts made while a launch file is being read (an include read without one).
RECORDER: list[Any] = [None]


class SubstitutionFailure(Exception):
    """A substitution could not be performed (real launch's launch.substitutions.SubstitutionFailure)."""


class EvaluationError(Exception):
    """The launch file asks for more than a launch may (processes, includes, entities)."""


class InvalidLaunchFileError(Exception):
    """A launch file could not be loaded."""


class Substitution:
    """Something that becomes text when the launch file is evaluated."""

    def perform(self, context: "LaunchContext") -> str:
        raise NotImplementedError

    def describe(self) -> str:
        return type(self).__name__


class TextSubstitution(Substitution):
    """Literal text."""

    def __init__(self, *, text: str) -> None:
        if not isinstance(text, str):
            raise TypeError(f"TextSubstitution expected Text object got '{type(text)}' instead.")
        self.text = text

    def perform(self, context: "LaunchContext") -> str:
        return self.text

    def describe(self) -> str:
        return repr(self.text)


SomeSubstitutionsType = Union[str, Substitution, Iterable[Union[str, Substitution]]]


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """A string, a substitution or a list of both, as a list of substitutions."""
    def one(item: Any) -> Substitution:
        if isinstance(item, Substitution):
            return item
        if isinstance(item, str):
            return TextSubstitution(text=item)
        raise TypeError(f"Failed to normalize given item of type '{type(item)}', when only 'str' or "
                        "'launch.Substitution' were expected.")
    if isinstance(subs, (str, Substitution)):
        return [one(subs)]
    if isinstance(subs, os.PathLike):
        return [TextSubstitution(text=os.fspath(subs))]
    return [one(item) for item in subs]


def perform_substitutions(context: "LaunchContext", subs: list[Substitution]) -> str:
    return "".join(context.perform_substitution(sub) for sub in subs)


class LaunchContext:
    """Launch configurations (scoped by groups), locals, environment and what the evaluator records."""

    def __init__(self, environment: dict[str, str] | None = None) -> None:
        self.launch_configurations: dict[str, Any] = {}
        self._configuration_stack: list[dict[str, Any]] = []
        self.environment: dict[str, str] = dict(os.environ if environment is None else environment)
        self._environment_stack: list[dict[str, str]] = []
        self.locals: dict[str, Any] = {}
        self._locals_stack: list[dict[str, Any]] = []
        self.argv: list[str] = []
        self.recorder: Any = RECORDER[0]  # the evaluator's: processes, logs, deferred entities

    def perform_substitution(self, sub: Substitution) -> str:
        return sub.perform(self)

    def push_launch_configurations(self) -> None:
        self._configuration_stack.append(dict(self.launch_configurations))

    def pop_launch_configurations(self) -> None:
        self.launch_configurations = self._configuration_stack.pop()

    def push_environment(self) -> None:
        self._environment_stack.append(dict(self.environment))

    def pop_environment(self) -> None:
        self.environment = self._environment_stack.pop()

    def extend_locals(self, values: dict[str, Any]) -> None:
        self.locals.update(values)

    def get_locals_as_dict(self) -> dict[str, Any]:
        return dict(self.locals)


class LaunchDescriptionEntity:
    """Anything a launch description holds."""

    def visit(self, context: LaunchContext) -> Optional[list["LaunchDescriptionEntity"]]:
        return None

    def describe_sub_entities(self) -> list["LaunchDescriptionEntity"]:
        return []

    def describe_conditional_sub_entities(self) -> list["LaunchDescriptionEntity"]:
        return []


class Condition:
    """Whether an action runs: a predicate of the context."""

    def __init__(self, *, predicate: Callable[[LaunchContext], bool] | None = None) -> None:
        self._predicate = predicate

    def evaluate(self, context: LaunchContext) -> bool:
        return bool(self._predicate(context)) if self._predicate else True


class Action(LaunchDescriptionEntity):
    """An action: executed when visited, unless its condition is false."""

    def __init__(self, *, condition: Condition | None = None) -> None:
        self.__condition = condition

    @property
    def condition(self) -> Condition | None:
        return self.__condition

    def visit(self, context: LaunchContext) -> Optional[list[LaunchDescriptionEntity]]:
        if self.__condition is None or self.__condition.evaluate(context):
            return self.execute(context)
        return None

    def execute(self, context: LaunchContext) -> Optional[list[LaunchDescriptionEntity]]:
        return None

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return []

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.get_sub_entities()


class LaunchDescription(LaunchDescriptionEntity):
    """The list of entities a launch file returns."""

    def __init__(self, initial_entities: Iterable[LaunchDescriptionEntity] | None = None, *,
                 deprecated_reason: str | None = None) -> None:
        self.__entities = list(initial_entities or [])
        self.deprecated_reason = deprecated_reason

    @property
    def entities(self) -> list[LaunchDescriptionEntity]:
        return self.__entities

    def add_entity(self, entity: LaunchDescriptionEntity) -> None:
        self.__entities.append(entity)

    def add_action(self, action: Action) -> None:
        self.add_entity(action)

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        return list(self.__entities)

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return list(self.__entities)

    def get_launch_arguments(self, conditional_inclusion: bool = False) -> list[Any]:
        """Every DeclareLaunchArgument found without running the launch (first declaration of a name wins)."""
        return [argument for argument, _ in self.get_launch_arguments_with_include_launch_description_actions(
            conditional_inclusion)]

    def get_launch_arguments_with_include_launch_description_actions(
            self, conditional_inclusion: bool = False) -> list[tuple[Any, Optional[list[Any]]]]:
        """The arguments with the includes they were found through (None: this file's own), as real launch finds
        them: includes are loaded without a context where their path allows it, and arguments under a condition,
        a timer or an event handler are marked conditionally included."""
        from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
        found: list[tuple[Any, Optional[list[Any]]]] = []

        def walk(entities: list[LaunchDescriptionEntity], conditional: bool, includes: Optional[list[Any]]) -> None:
            for entity in entities:
                if isinstance(entity, DeclareLaunchArgument):
                    if entity.name in [a.name for a, _ in found]:
                        continue
                    entity._conditionally_included = conditional or entity.condition is not None
                    found.append((entity, includes))
                nested = includes
                if isinstance(entity, IncludeLaunchDescription):
                    nested = [*(includes or []), entity]
                walk(entity.describe_sub_entities(), False, nested)
                walk(entity.describe_conditional_sub_entities(), True, nested)
        walk(self.__entities, conditional_inclusion, None)
        return found


class ExternalLaunchDescription(LaunchDescription):
    """What an include of a launch file of a package rosgrade provides itself (a simulator's world) stands for."""
