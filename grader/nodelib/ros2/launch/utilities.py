"""launch.utilities: what launch files import from it (substitution helpers)."""
from __future__ import annotations

from launch.core import normalize_to_list_of_substitutions, perform_substitutions

__all__ = ["normalize_to_list_of_substitutions", "perform_substitutions"]
