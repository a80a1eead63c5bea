"""Event handlers of ROS 2 launch: actions that run when a process starts or exits, or the launch shuts down."""
from __future__ import annotations

from typing import Any, Callable

__all__ = ["OnExecutionComplete", "OnProcessExit", "OnProcessIO", "OnProcessStart", "OnShutdown"]


class _OnProcess:
    """Runs its actions (or a function's) when the target process (any, when None) has the event."""

    event = ""

    def __init__(self, *, target_action: Any = None, handle_once: bool = False, **handler: Any) -> None:
        self.target_action = target_action
        self.handle_once = handle_once
        self.handler = next((v for k, v in handler.items() if k.startswith("on_")), None)

    def entities(self, event_info: dict[str, Any], context: Any) -> list[Any]:
        """What the handler returns for one event."""
        handler = self.handler
        if handler is None:
            return []
        if callable(handler) and not isinstance(handler, list):
            from launch.core import Action
            if isinstance(handler, Action):
                return [handler]
            result = handler(_Event(event_info), context)
            return [] if result is None else (list(result) if isinstance(result, (list, tuple)) else [result])
        return list(handler)


class _Event:
    """What a handler function receives: the event's process (its action and name) and exit code."""

    def __init__(self, info: dict[str, Any]) -> None:
        self.action = info.get("action")
        self.process_name = info.get("name", "")
        self.returncode = info.get("returncode", 0)
        self.reason = info.get("reason", "")


class OnProcessStart(_OnProcess):
    """When the process has started."""

    event = "start"

    def __init__(self, *, target_action: Any = None, on_start: Any = None, **kwargs: Any) -> None:
        super().__init__(target_action=target_action, on_start=on_start, **kwargs)


class OnProcessExit(_OnProcess):
    """When the process has exited."""

    event = "exit"

    def __init__(self, *, target_action: Any = None, on_exit: Any = None, **kwargs: Any) -> None:
        super().__init__(target_action=target_action, on_exit=on_exit, **kwargs)


class OnExecutionComplete(_OnProcess):
    """When an action has finished executing (for a process: it has been started)."""

    event = "start"

    def __init__(self, *, target_action: Any = None, on_completion: Any = None, **kwargs: Any) -> None:
        super().__init__(target_action=target_action, on_completion=on_completion, **kwargs)


class OnProcessIO(_OnProcess):
    """When the process prints: rosgrade does not run processes while reading the launch file, so never here."""

    event = "io"

    def __init__(self, *, target_action: Any = None, on_stdout: Any = None, on_stderr: Any = None,
                 on_stdin: Any = None, **kwargs: Any) -> None:
        super().__init__(target_action=target_action, **kwargs)


class OnShutdown(_OnProcess):
    """When the launch shuts down."""

    event = "shutdown"

    def __init__(self, *, on_shutdown: Callable[..., Any] | Any = None, **kwargs: Any) -> None:
        super().__init__(on_shutdown=on_shutdown, **kwargs)
