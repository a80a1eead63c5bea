"""rosgrade's ``ament_index_python``: packages as colcon would install the submission's (and the world's)."""
from __future__ import annotations

from ament_index_python.packages import (
    PackageNotFoundError, get_package_prefix, get_package_share_directory, get_packages_with_prefixes,
)

__all__ = ["PackageNotFoundError", "get_package_prefix", "get_package_share_directory", "get_packages_with_prefixes"]
