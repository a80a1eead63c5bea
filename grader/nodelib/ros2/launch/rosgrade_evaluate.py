"""Evaluates a launch file as `ros2 launch` would, inside the sandbox, and writes what it would start as JSON.

``python3 -m launch.rosgrade_evaluate FILE [name:=value ...]`` (``--show-args``: only the declared arguments). The
processes are listed in the order launch starts them: those started at once, then those an event handler starts on
another's start or exit, then those a TimerAction starts, by delay; each says what started it. Nothing is run.
The JSON goes to the file descriptor in ROSGRADE_LAUNCH_FD (stdout when unset), so that what the launch file prints
cannot forge it.
"""
from __future__ import annotations

import json
import os
import sys
import traceback
from typing import Any

from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.core import (
    RECORDER, Action, EvaluationError, ExternalLaunchDescription, InvalidLaunchFileError, LaunchContext,
    LaunchDescription, LaunchDescriptionEntity,
)
from launch.launch_description_sources import AnyLaunchDescriptionSource, load_python_launch_file_as_module

MAX_PROCESSES = 200  # a course launch file starts a handful; each is a process of the run
MAX_ENTITIES = 20_000
MAX_LOADS = 50  # launch files read in one launch (includes): more is an include that includes itself
MAX_PARAMS_FILE_BYTES = 1 << 20


class Recorder:
    """What launch would start and log, in order, with what started each."""

    def __init__(self) -> None:
        self.processes: list[dict[str, Any]] = []
        self.logs: list[dict[str, Any]] = []
        self.events: list[dict[str, Any]] = []
        self.external_includes: list[dict[str, Any]] = []
        self.arguments: dict[str, dict[str, Any]] = {}
        self.handlers: list[Any] = []
        self.queue: list[tuple[str, dict[str, Any], Any]] = []
        self.timers: list[tuple[float, int, list[LaunchDescriptionEntity], dict[str, Any]]] = []
        self.names: dict[int, str] = {}
        self.loads = 0
        self.entities = 0
        self.generated = 0
        self.files: list[str] = []

    def trigger(self, context: LaunchContext) -> dict[str, Any]:
        return dict(context.locals.get("rosgrade_trigger") or {"delay": 0.0, "after": None})

    def declared(self, action: DeclareLaunchArgument, context: LaunchContext) -> None:
        self.arguments.setdefault(action.name, {"name": action.name, "description": action.description,
                                                "value": context.launch_configurations[action.name]})

    def process(self, action: Action, description: dict[str, Any], context: LaunchContext) -> None:
        if len(self.processes) >= MAX_PROCESSES:
            raise EvaluationError(f"the launch file starts more than {MAX_PROCESSES} processes; a launch file for "
                                  "one robot starts a handful")
        description["name"] = f"{description['name']}-{len(self.processes) + 1}"
        record = {**description, **self.trigger(context)}
        self.processes.append(record)
        self.names[id(action)] = record["name"]
        self.queue.append(("start", record, action))

    def defer(self, delay: float, entities: list[LaunchDescriptionEntity], context: LaunchContext) -> None:
        trigger = self.trigger(context)
        trigger["delay"] = round(trigger["delay"] + delay, 9)
        self.timers.append((trigger["delay"], len(self.timers), entities, {**context.locals,
                                                                             "rosgrade_trigger": trigger}))

    def register(self, handler: Any, context: LaunchContext) -> None:
        self.handlers.append((handler, dict(context.locals)))

    def log(self, text: str, context: LaunchContext) -> None:
        self.logs.append({"text": text, **self.trigger(context)})

    def event(self, event: Any, context: LaunchContext) -> None:
        self.events.append({"event": "shutdown", "reason": str(getattr(event, "reason", "")), **self.trigger(context)})

    def params_file(self, path: str | None, content: str | None) -> dict[str, Any] | None:
        """A parameter file handed to a node: a generated one (its content), or the file at `path` (None if none)."""
        if path is None:
            self.generated += 1
            return {"path": f"/tmp/launch_params_{self.generated}", "generated": True, "content": content}
        if not os.path.isfile(path):
            print(f"[WARNING] [launch_ros.actions.node]: Parameter file path is not a file: {path}", file=sys.stderr)
            return None
        with open(path, encoding="utf-8", errors="replace") as handle:
            text = handle.read(MAX_PARAMS_FILE_BYTES)
        return {"path": path, "generated": False, "content": text}

    def load(self, path: str, kind: str, context: LaunchContext, record: bool = True) -> LaunchDescription:
        self.loads += 1
        if self.loads > MAX_LOADS:
            raise EvaluationError(f"more than {MAX_LOADS} launch files were included: {os.path.basename(path)} "
                                  "includes itself, directly or through another file")
        self.files.append(os.path.abspath(path))
        package = _not_ours(path)
        if package is not None:
            if record:
                self.external_includes.append({"package": package, "file": path, "arguments": {},
                                               **self.trigger(context)})
            return ExternalLaunchDescription()
        if not os.path.exists(path):
            raise InvalidLaunchFileError(f"[Errno 2] No such file or directory: '{path}'") \
                if kind != "any" else FileNotFoundError(2, "No such file or directory", path)
        if path.endswith(".py") or kind == "python":
            try:
                module = load_python_launch_file_as_module(path)
                if not hasattr(module, "generate_launch_description"):
                    raise InvalidLaunchFileError(f"launch file at '{path}' does not contain the required function "
                                                 "'generate_launch_description()'")
                description = module.generate_launch_description()
            except Exception as exc:
                if kind != "any":
                    raise
                raise InvalidLaunchFileError(
                    "Caught multiple exceptions when trying to load file of format [py]:\n"
                    f" - {type(exc).__name__}: {exc}\n - InvalidFrontendLaunchFileError: The launch file may have a "
                    "syntax error, or its format is unknown").with_traceback(exc.__traceback__) from None
        else:
            from launch.frontend import load_frontend
            description = load_frontend(path)
        if not isinstance(description, LaunchDescription):
            raise InvalidLaunchFileError(f"generate_launch_description() of '{path}' returned "
                                         f"{type(description).__name__}, not a LaunchDescription")
        return description

    def visit(self, entity: LaunchDescriptionEntity, context: LaunchContext) -> None:
        self.entities += 1
        if self.entities > MAX_ENTITIES:
            raise EvaluationError(f"the launch description holds more than {MAX_ENTITIES} actions")
        for inner in entity.visit(context) or []:
            self.visit(inner, context)

    def run_events(self, context: LaunchContext) -> None:
        """Start and exit events of the processes recorded so far (and of those their handlers start)."""
        exits: list[tuple[dict[str, Any], Any]] = []
        while self.queue or exits:
            if self.queue:
                kind, record, action = self.queue.pop(0)
                exits.append((record, action))
            else:
                kind, (record, action) = "exit", exits.pop(0)
            for handler, saved in list(self.handlers):
                if handler.event != kind or (handler.target_action is not None and handler.target_action is not action):
                    continue
                if handler.handle_once:
                    self.handlers.remove((handler, saved))
                trigger = {"delay": record["delay"], "after": {"event": kind, "process": record["name"]}}
                context.locals = {**saved, "rosgrade_trigger": trigger}
                info = {"action": action, "name": record["name"], "returncode": 0}
                for entity in handler.entities(info, context):
                    self.visit(entity, context)

    def run(self, context: LaunchContext, root: LaunchDescriptionEntity) -> None:
        self.visit(root, context)
        self.run_events(context)
        while self.timers:
            self.timers.sort(key=lambda t: (t[0], t[1]))
            _, _, entities, saved = self.timers.pop(0)
            context.locals = saved
            for entity in entities:
                self.visit(entity, context)
            self.run_events(context)
        for handler, saved in [h for h in self.handlers if h[0].event == "shutdown"]:
            context.locals = {**saved, "rosgrade_trigger": {"delay": 0.0, "after": {"event": "shutdown"}}}
            for entity in handler.entities({"reason": "launch ended"}, context):
                self.visit(entity, context)

    def result(self) -> dict[str, Any]:
        return {"processes": self.processes, "logs": self.logs, "events": self.events,
                "arguments": list(self.arguments.values()), "external_includes": self.external_includes}


def _not_ours(path: str) -> str | None:
    """The package whose launch file `path` is when that package is not the submission's (a simulator's, turtlesim's):
    rosgrade provides the world itself, so such an include starts nothing."""
    from ament_index_python.packages import index
    for name, entry in index().items():
        if (entry.get("external") or entry.get("world")) and path.startswith(entry["share"].rstrip("/") + "/"):
            return name
    return None


def _where(exc: BaseException, files: list[str]) -> str | None:
    """The launch file line the error came from (the innermost frame in one of the files read), if any."""
    if isinstance(exc, SyntaxError) and exc.filename:
        return f"{exc.filename}:{exc.lineno}"
    found = None
    for frame in traceback.extract_tb(exc.__traceback__):
        if os.path.abspath(frame.filename) in files:
            found = f"{frame.filename}:{frame.lineno}: {frame.line}"
    return found


def show_args(path: str, recorder: Recorder) -> list[dict[str, Any]]:
    """The arguments the file declares (as `ros2 launch --show-args`), without evaluating it."""
    context = LaunchContext()
    description = recorder.load(path, "any", context)
    return [{"name": a.name, "description": a.description,
             "default": None if a.default_value is None else " + ".join(s.describe() for s in a.default_value),
             "conditional": a._conditionally_included, "choices": a.choices}
            for a in description.get_launch_arguments()]


def evaluate(path: str, arguments: list[tuple[str, str]], only_args: bool = False) -> dict[str, Any]:
    recorder = Recorder()
    RECORDER[0] = recorder
    try:
        if only_args:
            return {"arguments": show_args(path, recorder), "error": None}
        context = LaunchContext()
        recorder.run(context, IncludeLaunchDescription(AnyLaunchDescriptionSource(path), launch_arguments=arguments))
        return {**recorder.result(), "error": None}
    except RecursionError:
        return {**recorder.result(), "error": {"message": "the launch description nests too deep (an include or "
                                                          "OpaqueFunction that returns itself?)", "where": None}}
    except Exception as exc:
        text = str(exc)
        message = text if isinstance(exc, EvaluationError) else \
            f"Caught exception in launch (see debug for traceback): {text}"
        return {**recorder.result(), "error": {"message": message, "type": type(exc).__name__,
                                               "where": _where(exc, recorder.files)}}


def main() -> None:
    words = sys.argv[1:]
    only_args = "--show-args" in words
    words = [w for w in words if w != "--show-args"]
    path, pairs = words[0], [tuple(w.split(":=", 1)) for w in words[1:]]
    result = evaluate(os.path.abspath(path), pairs, only_args)
    fd = int(os.environ.get("ROSGRADE_LAUNCH_FD", "1"))
    data = json.dumps(result, default=str).encode()
    with os.fdopen(fd, "wb", closefd=fd != 1) as out:
        out.write(data)
        out.flush()


if __name__ == "__main__":
    main()
