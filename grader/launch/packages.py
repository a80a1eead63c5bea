"""Find the catkin packages of a submission (a folder with a ``package.xml``), by the name ``package.xml`` gives."""
from __future__ import annotations

import os
import re
from pathlib import Path

from grader.runtime.scripts import SKIPPED_DIRS

_NAME = re.compile(rb"<name>\s*([^<\s]+)\s*</name>")
MAX_DEPTH = 6  # a workspace's src/<pkg>/package.xml is depth 2; deeper copies are not packages roslaunch would use


def package_name(folder: Path) -> str | None:
    """The ``<name>`` in ``folder/package.xml``, or None when there is none (or it cannot be read)."""
    try:
        match = _NAME.search((folder / "package.xml").read_bytes()[:65536])
    except OSError:
        return None
    return match.group(1).decode("utf-8", "replace") if match else None


def find_packages(root: Path) -> dict[str, Path]:
    """Every package under ``root`` by name (the shallowest, then the first in name order, when two share one)."""
    root = root if root.is_dir() else root.parent
    found: list[tuple[int, str, str, Path]] = []
    for folder, dirs, files in os.walk(root):
        depth = len(Path(folder).relative_to(root).parts)
        dirs[:] = [] if depth >= MAX_DEPTH else [d for d in dirs if not d.startswith(".") and d not in SKIPPED_DIRS]
        if "package.xml" in files:
            name = package_name(Path(folder))
            if name:
                found.append((depth, folder, name, Path(folder)))
    packages: dict[str, Path] = {}
    for _, _, name, folder in sorted(found):
        packages.setdefault(name, folder)
    return packages


def enclosing_package(path: Path) -> Path | None:
    """The nearest folder at or above ``path`` that holds a ``package.xml``."""
    for folder in [path, *path.parents] if path.is_dir() else path.parents:
        if (folder / "package.xml").is_file():
            return folder
    return None
