"""A submission's Python read by the grader (parsed, or compiled to find syntax errors) without printing its warnings.

Python warns while it compiles code such as ``"\\d"`` (an invalid escape: a SyntaxWarning since Python 3.12) or
``x is 0``. Those warnings are the student's node's to print, on its own stderr when it runs, and Python's to word;
the grader only reads the code, so its console and its notes must not change with them or with the Python it runs on.
"""
from __future__ import annotations

import ast
import warnings
from types import CodeType


def parse(source: str) -> ast.Module:
    """``ast.parse(source)``, silently; raises what ast.parse raises for code that does not parse."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ast.parse(source)


def compile_quietly(source: str, filename: str) -> CodeType:
    """``compile(source, filename, "exec")`` as a script is compiled, silently; raises what compile raises."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return compile(source, filename, "exec", dont_inherit=True)
