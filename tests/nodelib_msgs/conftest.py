"""Puts grader/nodelib first on sys.path, as a student's node process has it, so `import genpy` is ours."""
from __future__ import annotations

import sys
from pathlib import Path

NODELIB = str(Path(__file__).resolve().parents[2] / "grader" / "nodelib")
if NODELIB not in sys.path:
    sys.path.insert(0, NODELIB)
