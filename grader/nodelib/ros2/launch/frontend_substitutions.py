"""The `$(name args...)` substitution syntax of XML and YAML launch files, parsed into launch substitutions.

A template is text with substitutions in it; a substitution's arguments are separated by single spaces, may be
quoted with ' or ", and may hold substitutions themselves; a backslash escapes the next character.
"""
from __future__ import annotations

from typing import Any, Callable

from launch.core import Substitution, TextSubstitution


class SubstitutionSyntaxError(ValueError):
    """A `$(...)` that does not parse."""


def _make(name: str, args: list[list[Substitution]]) -> Substitution:
    from launch import substitutions as s
    from launch_ros import substitutions as r

    def arity(low: int, high: int) -> None:
        if not low <= len(args) <= high:
            raise TypeError(f"{name} substitution expects {low if low == high else f'{low} or {high}'} "
                            f"argument{'s' if high > 1 else ''}")

    makers: dict[str, Callable[[], Substitution]] = {
        "var": lambda: (arity(1, 2), s.LaunchConfiguration(args[0], default=args[1] if len(args) > 1 else None))[1],
        "env": lambda: (arity(1, 2), s.EnvironmentVariable(args[0], default_value=args[1] if len(args) > 1
                                                             else None))[1],
        "find-pkg-share": lambda: (arity(1, 1), r.FindPackageShare(args[0]))[1],
        "find-pkg-prefix": lambda: (arity(1, 1), r.FindPackagePrefix(args[0]))[1],
        "exec-in-pkg": lambda: (arity(2, 2), r.ExecutableInPackage(args[0], args[1]))[1],
        "eval": lambda: (arity(1, 1), s.PythonExpression(args[0]))[1],
        "dirname": lambda: (arity(0, 0), s.ThisLaunchFileDir())[1],
        "filename": lambda: (arity(0, 0), s.ThisLaunchFile())[1],
        "anon": lambda: (arity(1, 1), s.AnonName(args[0]))[1],
        "not": lambda: (arity(1, 1), s.NotSubstitution(args[0]))[1],
        "and": lambda: (arity(2, 2), s.AndSubstitution(args[0], args[1]))[1],
        "or": lambda: (arity(2, 2), s.OrSubstitution(args[0], args[1]))[1],
        "equals": lambda: (arity(2, 2), s.EqualsSubstitution(args[0], args[1]))[1],
        "not-equals": lambda: (arity(2, 2), s.NotSubstitution([s.EqualsSubstitution(args[0], args[1])]))[1],
        "command": lambda: s.Command(*args),
        "find-exec": lambda: (arity(1, 1), s.FindExecutable(name=args[0]))[1],
    }
    if name not in makers:
        raise SubstitutionSyntaxError(f"Unknown substitution: {name}")
    return makers[name]()


class _Reader:
    """A recursive-descent reader over one attribute's text."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.pos = 0

    def peek(self, n: int = 1) -> str:
        return self.text[self.pos:self.pos + n]

    def template(self, ends: str = "") -> list[Substitution]:
        """Text and substitutions until one of ``ends`` (a closing quote; a space or ')' after an argument), or the
        end of the text."""
        parts: list[Substitution] = []
        buffer = ""
        while self.pos < len(self.text) and self.peek() not in ends:
            if self.peek(2) == "$(":
                if buffer:
                    parts.append(TextSubstitution(text=buffer))
                    buffer = ""
                parts.append(self.substitution())
            elif self.peek() == "\\" and self.pos + 1 < len(self.text):
                buffer += self.text[self.pos + 1]
                self.pos += 2
            else:
                buffer += self.peek()
                self.pos += 1
        if buffer:
            parts.append(TextSubstitution(text=buffer))
        return parts

    def substitution(self) -> Substitution:
        start = self.pos
        self.pos += 2
        name = ""
        while self.pos < len(self.text) and (self.peek().isalnum() or self.peek() in "_-"):
            name += self.peek()
            self.pos += 1
        if not name:
            raise SubstitutionSyntaxError(f"no substitution name after '$(' in {self.text!r}")
        args: list[list[Substitution]] = []
        while self.peek() == " ":
            self.pos += 1
            args.append(self.argument())
        if self.peek() != ")":
            raise SubstitutionSyntaxError(f"unclosed substitution starting at {self.text[start:]!r}")
        self.pos += 1
        return _make(name, args)

    def argument(self) -> list[Substitution]:
        if self.peek() in ("'", '"'):
            quote = self.peek()
            self.pos += 1
            value = self.template(ends=quote)
            if self.peek() != quote:
                raise SubstitutionSyntaxError(f"unclosed quote in {self.text!r}")
            self.pos += 1
            return value or [TextSubstitution(text="")]
        return self.template(ends=" )")


def parse_substitution(text: Any) -> list[Substitution]:
    """A template's substitutions (plain text: one TextSubstitution)."""
    text = str(text)
    if not text:
        return [TextSubstitution(text="")]
    return _Reader(text).template()


def is_plain(parts: list[Substitution]) -> bool:
    return len(parts) == 1 and isinstance(parts[0], TextSubstitution)
