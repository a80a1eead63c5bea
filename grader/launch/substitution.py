"""``$(...)`` substitutions in launch-file attributes: arg, find, env, optenv, anon, dirname and eval.

``$(eval ...)`` runs a student's Python expression inside the grader, so it is parsed first and only a small set
of expression forms (names, literals, arithmetic, comparisons, calls to the roslaunch helpers and a few builtins)
is allowed: no attribute starting with ``_``, no imports, no lambdas or comprehensions; ``*`` and ``**`` check
their operands before they run, so an expression cannot build a huge value.
"""
from __future__ import annotations

import ast
import re
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from grader.launch.values import convert

_COMMAND = re.compile(r"\$\(([^()]*)\)")
_EVAL_PREFIX = "$(eval "
_SAFE_BUILTINS: dict[str, object] = {
    name: __builtins__[name] if isinstance(__builtins__, dict) else getattr(__builtins__, name)
    for name in ("abs", "all", "any", "bool", "float", "int", "len", "max", "min", "round", "str", "sorted", "sum",
                 "list", "tuple")
}
_ALLOWED_NODES = (
    ast.Expression, ast.BoolOp, ast.And, ast.Or, ast.BinOp, ast.Add, ast.Sub, ast.Mult, ast.Div, ast.FloorDiv,
    ast.Mod, ast.UnaryOp, ast.Not, ast.USub, ast.UAdd, ast.Compare, ast.Eq, ast.NotEq, ast.Lt, ast.LtE, ast.Gt,
    ast.GtE, ast.In, ast.NotIn, ast.Is, ast.IsNot, ast.IfExp, ast.Call, ast.keyword, ast.Name, ast.Load,
    ast.Constant, ast.List, ast.Tuple, ast.Subscript, ast.Slice, ast.Attribute, ast.Pow,
)
MAX_EVAL_CHARS = 500
# eval runs in the grader's own process: `*` and `**` are checked before they run, so no value grows huge.
MAX_EVAL_ITEMS = 100_000
MAX_EVAL_EXPONENT = 64
MAX_EVAL_BASE = 10**9
_UNSAFE_ATTRIBUTES = {"format", "format_map", "mro"}


class SubstitutionError(Exception):
    """A ``$(...)`` cannot be resolved; the message says which and why (the reader adds the file and line)."""


@dataclass(frozen=True)
class Scope:
    """What substitutions can see at one place of a launch file."""

    arg: Callable[[str], str]
    find: Callable[[str], str]
    anon: Callable[[str], str]
    env: Mapping[str, str]
    dirname: str
    arg_names: Callable[[], dict[str, str]]  # every arg with a value, for $(eval)


def substitute(text: str, scope: Scope) -> str:
    """``text`` with every ``$(command ...)`` replaced; a whole-value ``$(eval expr)`` is evaluated."""
    if text.startswith(_EVAL_PREFIX) and text.endswith(")"):
        return _evaluate(text[len(_EVAL_PREFIX):-1], scope)
    return _COMMAND.sub(lambda match: _command(match.group(1), scope), text)


def _command(inner: str, scope: Scope) -> str:
    words = inner.split()
    if not words:
        raise SubstitutionError("empty substitution $()")
    command, args = words[0], words[1:]
    if command == "eval":
        raise SubstitutionError("$(eval ...) must be the whole attribute value, e.g. if=\"$(eval x > 1)\"")
    if command == "optenv":
        if not args:
            raise SubstitutionError("$(optenv VAR [default]) needs a variable name")
        return scope.env.get(args[0], " ".join(args[1:]))
    if command == "dirname":
        if args:
            raise SubstitutionError("$(dirname) takes no argument")
        return scope.dirname
    handlers: dict[str, Callable[[str], str]] = {"arg": scope.arg, "find": scope.find, "anon": scope.anon,
                                                  "env": lambda name: _env(scope.env, name)}
    if command not in handlers:
        raise SubstitutionError(f"unknown substitution $({inner}); expected one of arg, find, env, optenv, "
                                "anon, dirname, eval")
    if len(args) != 1:
        raise SubstitutionError(f"$({command} ...) takes exactly one argument (got $({inner}))")
    return handlers[command](args[0])


def _env(env: Mapping[str, str], name: str) -> str:
    if name not in env:
        raise SubstitutionError(f"environment variable '{name}' is not set ($(env {name})); "
                                f"use $(optenv {name} default) for a value that may be missing")
    return env[name]


def _evaluate(expression: str, scope: Scope) -> str:
    if "__" in expression:
        raise SubstitutionError("$(eval ...) may not contain double underscores")
    if len(expression) > MAX_EVAL_CHARS:
        raise SubstitutionError(f"$(eval ...) is longer than {MAX_EVAL_CHARS} characters")
    try:
        with warnings.catch_warnings():  # an invalid escape warns on Python >= 3.12: the student's, not the grader's
            warnings.simplefilter("ignore")
            tree = ast.parse(expression.strip(), mode="eval")
    except SyntaxError as exc:
        raise SubstitutionError(f"$(eval {expression}) is not a Python expression: {exc.msg}") from None
    for node in ast.walk(tree):
        if not isinstance(node, _ALLOWED_NODES):
            raise SubstitutionError(f"$(eval {expression}): {type(node).__name__} is not allowed in the grader")
        if isinstance(node, ast.Attribute) and (node.attr.startswith("_") or node.attr in _UNSAFE_ATTRIBUTES):
            raise SubstitutionError(f"$(eval {expression}): attribute {node.attr} is not allowed in the grader")
    # As in roslaunch, an arg is typed like a <param> value (so `x > 1` compares numbers), and the helper
    # functions win over args of the same name.
    names: dict[str, object] = {name: convert(value, "auto") for name, value in scope.arg_names().items()}
    names |= {
        "true": True, "false": False, "True": True, "False": False,
        "arg": lambda name: convert(scope.arg(name), "auto"), "find": scope.find, "anon": scope.anon,
        "env": lambda name: _env(scope.env, name),
        "optenv": lambda name, default="": scope.env.get(name, default), "dirname": lambda: scope.dirname,
    }
    names |= {"_times": _times, "_power": _power}
    tree = ast.fix_missing_locations(_CheckedArithmetic().visit(tree))
    try:
        value = eval(compile(tree, "<eval>", "eval"), {"__builtins__": _SAFE_BUILTINS}, names)  # noqa: S307
    except SubstitutionError:
        raise
    except Exception as exc:  # the student's expression failed: say how, in their terms
        raise SubstitutionError(f"$(eval {expression}) failed: {type(exc).__name__}: {exc}") from None
    return str(value)


class _CheckedArithmetic(ast.NodeTransformer):
    """Rewrites ``a * b`` and ``a ** b`` as calls that check their operands first."""

    def visit_BinOp(self, node: ast.BinOp) -> ast.AST:
        self.generic_visit(node)
        checked = {ast.Mult: "_times", ast.Pow: "_power"}.get(type(node.op))
        if checked is None:
            return node
        return ast.Call(func=ast.Name(id=checked, ctx=ast.Load()), args=[node.left, node.right], keywords=[])


def _times(left: object, right: object) -> object:
    for sequence, count in ((left, right), (right, left)):
        if isinstance(sequence, (str, list, tuple)) and isinstance(count, int):
            if len(sequence) * max(count, 0) > MAX_EVAL_ITEMS:
                raise SubstitutionError(f"$(eval ...) would build a value of more than {MAX_EVAL_ITEMS} items")
    return left * right  # type: ignore[operator]


def _power(base: object, exponent: object) -> object:
    if isinstance(exponent, (int, float)) and abs(exponent) > MAX_EVAL_EXPONENT:
        raise SubstitutionError(f"$(eval ...): exponents above {MAX_EVAL_EXPONENT} are not allowed")
    if isinstance(base, int) and abs(base) > MAX_EVAL_BASE:
        raise SubstitutionError(f"$(eval ...): ** of numbers above {MAX_EVAL_BASE} is not allowed")
    return base ** exponent  # type: ignore[operator]
