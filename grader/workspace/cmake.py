"""Read a CMakeLists.txt as data: its commands and their arguments, with variables expanded, never run by CMake.

Only what colcon and catkin would act on for a beginner's package matters here (``project``, ``set``, ``install``,
``ament_python_install_package``, ``rosidl_generate_interfaces``, ...), so flow control is not evaluated: a command
inside an ``if()`` counts as if its branch were taken. Input is bounded (size, commands, the length a variable may
grow to) and a file CMake itself would refuse raises CMakeError with CMake's own wording and line.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from grader.workspace.manifest import read_regular

MAX_BYTES = 256 * 1024  # a course package's CMakeLists.txt is about 1 kB
MAX_COMMANDS = 4000
MAX_VALUE_CHARS = 8192  # set(A ${A}${A}) repeated would otherwise double without bound
_EXPANSIONS = 8  # ${${name}} nests; deeper is refused
_VARIABLE = re.compile(r"\$(?:ENV)?\{([^${}]*)\}")
_BRACKET_OPEN = re.compile(r"\[(=*)\[")
_HELD = "\0"  # stands for a '$' that came from a variable's value, which CMake does not expand again


class CMakeError(Exception):
    """CMake would refuse the file (a parse error), or it is too large to be a package's CMakeLists.txt."""


@dataclass(frozen=True)
class Command:
    """One command call: its name in lower case (CMake's names are case-insensitive), raw arguments and line."""

    name: str
    args: tuple[tuple[str, bool], ...]  # (text, quoted): unquoted arguments split on ';' once expanded
    line: int


def _error(line: int, what: str) -> CMakeError:
    return CMakeError(f"CMake Error at CMakeLists.txt:{line}: Parse error. {what}")


class _Scanner:
    """CMake's command-invocation grammar over one file's text."""

    def __init__(self, text: str) -> None:
        self.text, self.i, self.line = text, 0, 1

    def _bracket(self, start_line: int, what: str) -> str:
        """The body of a bracket argument or comment starting at self.i (at its first '[')."""
        match = _BRACKET_OPEN.match(self.text, self.i)
        assert match is not None
        close = "]" + match.group(1) + "]"
        end = self.text.find(close, match.end())
        if end < 0:
            raise _error(start_line, f"{what} is missing its closing \"{close}\".")
        body = self.text[match.end():end]
        self.line += self.text.count("\n", self.i, end + len(close))
        self.i = end + len(close)
        return body[1:] if body.startswith("\n") else body

    def _comment(self) -> None:
        self.i += 1
        if _BRACKET_OPEN.match(self.text, self.i):
            self._bracket(self.line, "A bracket comment")
            return
        end = self.text.find("\n", self.i)
        self.i = len(self.text) if end < 0 else end

    def _quoted(self) -> str:
        start, out = self.line, []
        self.i += 1
        while self.i < len(self.text):
            c = self.text[self.i]
            if c == '"':
                self.i += 1
                return "".join(out)
            if c == "\\" and self.i + 1 < len(self.text):
                nxt = self.text[self.i + 1]
                if nxt == "\n":  # a line continuation
                    self.line += 1
                else:
                    out.append({"n": "\n", "t": "\t", "r": "\r"}.get(nxt, nxt))
                self.i += 2
                continue
            self.line += c == "\n"
            out.append(c)
            self.i += 1
        raise _error(start, "Function missing ending \")\". End of file reached (a quoted argument is not closed).")

    def _unquoted(self) -> str:
        out = []
        while self.i < len(self.text):
            c = self.text[self.i]
            if c in " \t\r\n()#\"":
                break
            if c == "\\" and self.i + 1 < len(self.text):
                out.append(self.text[self.i + 1])
                self.i += 2
                continue
            out.append(c)
            self.i += 1
        return "".join(out)

    def _arguments(self, start: int) -> list[tuple[str, bool]]:
        args: list[tuple[str, bool]] = []
        depth = 1
        while self.i < len(self.text):
            c = self.text[self.i]
            if c == "\n":
                self.line += 1
                self.i += 1
            elif c in " \t\r":
                self.i += 1
            elif c == "#":
                self._comment()
            elif c == "(":
                depth += 1
                self.i += 1
            elif c == ")":
                depth -= 1
                self.i += 1
                if depth == 0:
                    return args
            elif c == '"':
                args.append((self._quoted(), True))
            elif c == "[" and _BRACKET_OPEN.match(self.text, self.i):
                args.append((self._bracket(self.line, "A bracket argument"), True))
            else:
                args.append((self._unquoted(), False))
        raise _error(start, "Function missing ending \")\". End of file reached.")

    def commands(self) -> list[Command]:
        found: list[Command] = []
        name = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
        while self.i < len(self.text):
            c = self.text[self.i]
            if c == "\n":
                self.line += 1
                self.i += 1
            elif c in " \t\r":
                self.i += 1
            elif c == "#":
                self._comment()
            else:
                match = name.match(self.text, self.i)
                if match is None:
                    raise _error(self.line, f"Expected a command name, got \"{c}\".")
                self.i = match.end()
                while self.i < len(self.text) and self.text[self.i] in " \t":
                    self.i += 1
                if self.i >= len(self.text) or self.text[self.i] != "(":
                    raise _error(self.line, f"Expected \"(\" after the command name {match.group()}.")
                start = self.line
                self.i += 1
                found.append(Command(match.group().lower(), tuple(self._arguments(start)), start))
                if len(found) > MAX_COMMANDS:
                    raise CMakeError(f"CMakeLists.txt has more than {MAX_COMMANDS} commands; a package's is a few "
                                     "dozen lines. Keep only what builds your package.")
        return found


def parse(text: str) -> list[Command]:
    """The commands of a CMakeLists.txt's text, in order (CMakeError if CMake could not parse it)."""
    if len(text) > MAX_BYTES:
        raise CMakeError(f"CMakeLists.txt is {len(text) >> 10} KiB; a package's is a few kB (limit "
                         f"{MAX_BYTES >> 10} KiB). Keep only what builds your package.")
    return _Scanner(text).commands()


def read(path: Path) -> list[Command]:
    """parse() of the file at ``path``, read at most MAX_BYTES + 1 bytes (CMakeError if unreadable or too large)."""
    try:
        raw = read_regular(path, MAX_BYTES + 1)
    except OSError as exc:
        raise CMakeError(f"CMakeLists.txt cannot be read ({exc.strerror}).") from None
    return parse(raw.decode("utf-8", "replace"))


class Variables:
    """CMake variables as ``set()`` and ``project()`` leave them, for expanding ``${...}`` in arguments."""

    def __init__(self, initial: dict[str, str]) -> None:
        self.values = dict(initial)

    def expand(self, text: str, line: int) -> str:
        """``text`` with every ``${name}`` replaced (an undefined one by nothing), innermost first for
        ``${${name}}``; as in CMake, a value's own ``${...}`` text is not expanded again."""
        def value(match: re.Match[str]) -> str:
            return self.values.get(match.group(1).replace(_HELD, "$"), "").replace("$", _HELD)

        for _ in range(_EXPANSIONS):
            expanded = _VARIABLE.sub(value, text)
            if len(expanded) > MAX_VALUE_CHARS:
                raise CMakeError(f"CMakeLists.txt line {line}: a variable grows past {MAX_VALUE_CHARS} characters.")
            if expanded == text:
                return text.replace(_HELD, "$")
            text = expanded
        raise CMakeError(f"CMakeLists.txt line {line}: variable references nest more than {_EXPANSIONS} deep.")

    def arguments(self, command: Command) -> list[str]:
        """The command's arguments as CMake hands them over: expanded, unquoted ones split into list items."""
        out: list[str] = []
        for text, quoted in command.args:
            value = self.expand(text, command.line)
            out += [value] if quoted else [item for item in value.split(";") if item]
        return out
