"""A run's own interface types (the submission's), given by the grader at START, added to the definition table."""
from __future__ import annotations

import json

from . import _defs

# action type -> RIHS01 (the built-in ones, then the run's); its messages are MESSAGES[type + '_Goal' / '_Result' / '_Feedback' / '_FeedbackMessage'],
# its services SERVICES[type + '_SendGoal' / '_GetResult'].
ACTIONS: dict[str, str] = dict(_defs.ACTIONS)


class InterfaceTableError(ValueError):
    """START's interfaces are not a definition table."""


def register(payload: dict) -> list[str]:
    """Add ``{"messages": {type: [fields, constants, RIHS01]}, "services": {type: RIHS01}, "actions": {...}}`` to
    the tables, before any class is built; returns the packages they belong to. Built-in types are never replaced."""
    try:
        messages = {name: json.dumps(entry) for name, entry in payload.get("messages", {}).items()
                    if name not in _defs.MESSAGES}
        services = {str(k): str(v) for k, v in payload.get("services", {}).items() if k not in _defs.SERVICES}
        actions = {str(k): str(v) for k, v in payload.get("actions", {}).items()}
    except (AttributeError, TypeError, ValueError) as exc:
        raise InterfaceTableError(f"START's interfaces are malformed: {exc}") from None
    _defs.MESSAGES.update(messages)
    _defs.SERVICES.update(services)
    ACTIONS.update(actions)
    return sorted({name.split("/")[0] for name in (*messages, *services, *actions)})
