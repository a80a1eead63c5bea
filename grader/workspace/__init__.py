"""A submission's ROS packages as their build would install them (``read_workspace``), read as data, never run."""
from __future__ import annotations

from grader.workspace.model import (
    Executable, Interface, Package, PythonPackage, Workspace, WorkspaceError, enclosing_folder, package_name,
    read_package, read_workspace,
)

__all__ = ["Executable", "Interface", "Package", "PythonPackage", "Workspace", "WorkspaceError", "enclosing_folder",
           "package_name", "read_package", "read_workspace"]
