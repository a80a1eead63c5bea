"""Makes a submission's own interface packages importable in the node, for either client library's message runtime.

A finder first on ``sys.meta_path`` answers ``pkg`` and ``pkg.<namespace>`` for the submission's packages with lazy
modules, as the static message packages are. A Python package of the same name on the path (catkin_python_setup,
ament_python_install_package) keeps its ``pkg`` module; its message submodules are still these, as catkin's devel
space and colcon merge them.
"""
from __future__ import annotations

import importlib.abc
import importlib.machinery
import sys
import types
from collections.abc import Callable

LazyExports = Callable[[str], tuple[Callable, Callable, list[str]]]


class _Loader(importlib.abc.Loader):
    def __init__(self, lazy_exports: LazyExports, runtime: str) -> None:
        self.lazy_exports = lazy_exports
        self.runtime = runtime

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> types.ModuleType | None:
        return None

    def exec_module(self, module: types.ModuleType) -> None:
        if module.__name__.count(".") == 1:
            module_getattr, module_dir, names = self.lazy_exports(module.__name__)
            module.__getattr__, module.__dir__, module.__all__ = module_getattr, module_dir, names  # type: ignore
        else:
            module.__doc__ = f"{module.__name__}: the submission's interfaces ({self.runtime})."


class _Finder(importlib.abc.MetaPathFinder):
    def __init__(self, packages: frozenset[str], namespaces: tuple[str, ...], loader: _Loader) -> None:
        self.packages = packages
        self.namespaces = namespaces
        self.loader = loader

    def find_spec(self, fullname: str, path: object = None,
                  target: object = None) -> importlib.machinery.ModuleSpec | None:
        parts = fullname.split(".")
        if parts[0] not in self.packages or len(parts) > 2 or (len(parts) == 2 and parts[1] not in self.namespaces):
            return None
        if len(parts) == 1:
            if importlib.machinery.PathFinder.find_spec(fullname) is not None:
                return None  # the workspace's own Python package of that name
            return importlib.machinery.ModuleSpec(fullname, self.loader, is_package=True)
        return importlib.machinery.ModuleSpec(fullname, self.loader, is_package=False)


def make_importable(packages: frozenset[str], namespaces: tuple[str, ...], lazy_exports: LazyExports,
                    runtime: str) -> None:
    """Serve ``packages`` (and their ``namespaces``: msg, srv, action) from the message runtime's lazy modules."""
    if packages:
        sys.meta_path.insert(0, _Finder(packages, namespaces, _Loader(lazy_exports, runtime)))
