"""rosgrade's grader: runs student nodes against the simulated world, records, scores and reports."""
from __future__ import annotations

__version__ = "0.1.0"
