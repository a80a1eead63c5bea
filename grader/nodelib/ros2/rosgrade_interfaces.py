"""The submission's own ROS 2 interface packages in the node: ``from my_interfaces.srv import MyNumberGame`` works.

The grader gives their definitions at START (rosgrade_rosidl's table format); this adds them to the table and puts
a finder first on ``sys.meta_path`` that makes ``pkg``, ``pkg.msg``, ``pkg.srv`` and ``pkg.action`` lazy modules,
as the static message packages beside this file are. A Python package of the same name on the path keeps its
``pkg`` module; its ``msg``/``srv``/``action`` submodules are still these, as colcon merges them.
"""
from __future__ import annotations

import importlib.abc
import importlib.machinery
import sys
import types

from rosgrade_rosidl._extra import register
from rosgrade_rosidl._package import lazy_module

_NAMESPACES = ("msg", "srv", "action")


class _Loader(importlib.abc.Loader):
    def create_module(self, spec: importlib.machinery.ModuleSpec) -> types.ModuleType | None:
        return None

    def exec_module(self, module: types.ModuleType) -> None:
        if module.__name__.count(".") == 1:
            module_getattr, module_dir, names = lazy_module(module.__name__)
            module.__getattr__, module.__dir__, module.__all__ = module_getattr, module_dir, names  # type: ignore
        else:
            module.__doc__ = f"{module.__name__}: the submission's interfaces (rosgrade's rosidl runtime)."


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
    """Add START's interfaces and make their packages importable."""
    packages = register(payload)
    if packages:
        sys.meta_path.insert(0, _Finder(frozenset(packages)))
