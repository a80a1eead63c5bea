"""Running student nodes: processes, the lockstep loop with the world, limits, diagnostics and script checks."""
from __future__ import annotations

from grader.runtime.scripts import ScriptNotFound, check_script, find_script
from grader.runtime.spec import Limits, NodeOutcome, NodeSpec, RunResult, RunSpec

__all__ = ["Limits", "NodeOutcome", "NodeSpec", "RunResult", "RunSpec", "ScriptNotFound", "check_script",
           "find_script"]
