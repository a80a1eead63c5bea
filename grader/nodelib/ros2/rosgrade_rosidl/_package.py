"""The lazy body of a package's ``msg``/``srv``/``action`` module: classes are built on first attribute access."""
from __future__ import annotations

from typing import Any, Callable

from ._classes import action_class, message_class, service_class
from ._defs import MESSAGES, SERVICES
from ._extra import ACTIONS


def lazy_module(module_name: str) -> tuple[Callable[[str], Any], Callable[[], list[str]], list[str]]:
    """``(__getattr__, __dir__, __all__)`` for the module ``pkg.msg``, ``pkg.srv`` or ``pkg.action``."""
    package, namespace = module_name.split(".")
    prefix = f"{package}/{namespace}/"
    if namespace == "srv":
        services = [n[len(prefix):] for n in SERVICES if n.startswith(prefix)]
        # rosidl_generator_py's srv module names each service's parts too (SetParameters_Request, ...)
        parts = [f"{n}_{part}" for n in services for part in ("Event", "Request", "Response")]
        names = sorted(services + parts)

        def build(type_name: str) -> Any:
            return message_class(type_name) if type_name.rsplit("/", 1)[1] in parts else service_class(type_name)
    elif namespace == "action":
        names = sorted(n[len(prefix):] for n in ACTIONS if n.startswith(prefix))
        build = action_class
    else:
        names = sorted(n[len(prefix):] for n in MESSAGES if n.startswith(prefix))
        build = message_class
    known = frozenset(names)

    def __getattr__(name: str) -> Any:
        if name not in known:
            raise AttributeError(f"module {module_name!r} has no attribute {name!r}")
        return build(prefix + name)

    def __dir__() -> list[str]:
        return list(names)
    return __getattr__, __dir__, list(names)
