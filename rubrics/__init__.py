"""The task rubrics: one TOML file per task (``<task id>.toml``), loaded by ``grader.rubric.load_rubrics``."""
from __future__ import annotations
