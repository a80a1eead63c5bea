"""The submission's own ROS 1 message packages in the node: ``from my_msgs.srv import AddInts`` works.

The grader gives their definitions at START (genpy._msgdefs' format: comment-free text with full type names); this
adds them to the table and puts a finder first on ``sys.meta_path`` that makes ``pkg``, ``pkg.msg`` and ``pkg.srv``
lazy modules, as the static message packages beside this file are. A Python package of the same name on the path
(catkin_python_setup) keeps its ``pkg`` module; its ``msg``/``srv`` submodules are still these, as catkin's
devel space merges them.
"""
from __future__ import annotations

import importlib.abc
import importlib.machinery
import sys
import types

from genpy import _msgdefs
from genpy._builder import lazy_exports

_NAMESPACES = ("msg", "srv")


class InterfaceTableError(ValueError):
    """START's interfaces are not a definition table."""


class _Loader(importlib.abc.Loader):
    def create_module(self, spec: importlib.machinery.ModuleSpec) -> types.ModuleType | None:
        return None

    def exec_module(self, module: types.ModuleType) -> None:
        if module.__name__.count(".") == 1:
            module_getattr, module_dir, names = lazy_exports(module.__name__)
            module.__getattr__, module.__dir__, module.__all__ = module_getattr, module_dir, names  # type: ignore
        else:
            module.__doc__ = f"{module.__name__}: the submission's messages (rosgrade's genpy)."


class _Finder(importlib.abc.MetaPathFinder):
    def __init__(self, packages: frozenset[str]) -> None:
        self.packages = packages
        self.loader = _Loader()

    def find_spec(self, fullname: str, path: object = None,
                  target: object = None) -> importlib.machinery.ModuleSpec | None:
        parts = fullname.split(".")
        if parts[0] not in self.packages or len(parts) > 2 or (len(parts) == 2 and parts[1] not in _NAMESPACES):
            return None
        if len(parts) == 1:
            if importlib.machinery.PathFinder.find_spec(fullname) is not None:
                return None  # the workspace's own Python package of that name
            return importlib.machinery.ModuleSpec(fullname, self.loader, is_package=True)
        return importlib.machinery.ModuleSpec(fullname, self.loader, is_package=False)


def install(payload: dict) -> None:
    """Add START's ``{"messages": {pkg/Name: text}, "services": {pkg/Name: "request---response"}}`` (built-in
    types are never replaced) and make their packages importable."""
    try:
        messages = {str(k): str(v) for k, v in payload.get("messages", {}).items() if k not in _msgdefs.MESSAGES}
        services = {str(k): str(v) for k, v in payload.get("services", {}).items() if k not in _msgdefs.SERVICES}
    except (AttributeError, TypeError) as exc:
        raise InterfaceTableError(f"START's interfaces are malformed: {exc}") from None
    _msgdefs.MESSAGES.update(messages)
    _msgdefs.SERVICES.update(services)
    packages = frozenset(name.split("/")[0] for name in (*messages, *services))
    if packages:
        sys.meta_path.insert(0, _Finder(packages))
