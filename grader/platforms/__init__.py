"""Outputs for grading platforms and CI: Gradescope, GitHub Classroom/Actions, PrairieLearn and JUnit XML."""
from __future__ import annotations
