"""Find the packages of a submission (a folder with a ``package.xml``) by the name ``package.xml`` gives, through the
workspace model (``grader.workspace``), which is the one place that walks a submission's folders for packages."""
from __future__ import annotations

from pathlib import Path

from grader.workspace import WorkspaceError, enclosing_folder, package_name, read_workspace
from grader.workspace.model import MAX_DEPTH

__all__ = ["MAX_DEPTH", "enclosing_package", "find_packages", "package_name"]


def find_packages(root: Path) -> dict[str, Path]:
    """Every package under ``root`` by name (the shallowest, then the first in name order, when two share one)."""
    try:
        return read_workspace(root if root.is_dir() else root.parent).folders
    except WorkspaceError:  # nothing there: no packages, as roslaunch would find none
        return {}


def enclosing_package(path: Path) -> Path | None:
    """The nearest folder at or above ``path`` that holds a ``package.xml``."""
    return enclosing_folder(path)
