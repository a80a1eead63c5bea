"""rosgrade's rospkg: find the catkin packages of the submission by their package.xml, as RosPack does.

Packages are looked for under ROS_PACKAGE_PATH when it is set, and in the workspace around the running script
(the folder holding the nearest package.xml above it, and that folder's parent: a catkin ``src``).
"""
from __future__ import annotations

import os
import re
import sys
from pathlib import Path

__all__ = ["ResourceNotFound", "RosPack", "get_ros_package_path", "get_ros_paths"]

_NAME = re.compile(r"<name>\s*([^<\s]+)\s*</name>")
_DEPTH = 4  # package.xml files this deep under a search root are found


class ResourceNotFound(Exception):
    """No package of that name exists on the package path."""

    def __init__(self, msg, ros_paths=None) -> None:
        super().__init__(msg)
        self.ros_paths = ros_paths

    def __str__(self) -> str:
        text = self.args[0] if self.args else ""
        for i, path in enumerate(self.ros_paths or ()):
            text += "\nROS path [%s]=%s" % (i, path)
        return text


def get_ros_package_path() -> str | None:
    return os.environ.get("ROS_PACKAGE_PATH")


def get_ros_paths() -> list[str]:
    """Where packages are searched: ROS_PACKAGE_PATH, else the workspace around the running script."""
    configured = get_ros_package_path()
    if configured:
        return [p for p in configured.split(os.pathsep) if p]
    script = Path(sys.argv[0]).resolve().parent if sys.argv and sys.argv[0] else Path.cwd()
    for folder in (script, *script.parents[:2]):
        if (folder / "package.xml").is_file():
            return [str(folder.parent), str(folder)]
    return [str(script)]


def _package_name(manifest: Path) -> str | None:
    try:
        found = _NAME.search(manifest.read_text(encoding="utf-8", errors="replace"))
    except OSError:
        return None
    return found.group(1) if found else None


class RosPack:
    """Package lookup by name over the search roots (found once, on first use)."""

    def __init__(self, ros_paths=None) -> None:
        self._ros_paths = list(ros_paths) if ros_paths is not None else get_ros_paths()
        self._packages: dict[str, str] | None = None

    def _index(self) -> dict[str, str]:
        if self._packages is None:
            self._packages = {}
            for root in self._ros_paths:
                for manifest in sorted(self._manifests(Path(root), _DEPTH)):
                    name = _package_name(manifest)
                    if name is not None:
                        self._packages.setdefault(name, str(manifest.parent))
        return self._packages

    @staticmethod
    def _manifests(root: Path, depth: int) -> list[Path]:
        if (root / "package.xml").is_file():
            return [root / "package.xml"]  # a package does not hold packages
        if depth == 0 or not root.is_dir():
            return []
        found = []
        try:
            children = sorted(p for p in root.iterdir() if p.is_dir() and not p.name.startswith("."))
        except OSError:
            return []
        for child in children:
            found += RosPack._manifests(child, depth - 1)
        return found

    def get_path(self, name) -> str:
        """The folder of package ``name``; ResourceNotFound when there is none."""
        try:
            return self._index()[name]
        except KeyError:
            raise ResourceNotFound(name, ros_paths=self._ros_paths) from None

    def list(self) -> list[str]:
        return sorted(self._index())

    def get_depends(self, name, implicit=True) -> list[str]:
        self.get_path(name)
        return []
