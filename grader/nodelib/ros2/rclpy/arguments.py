"""The ``--ros-args`` command line as rcl reads it: parameter files and ``-p`` values, remaps, log levels."""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from rosgrade_param_files import ParamFileError, ParamSet

from ._rclpy_pybind11 import RCLError
from .logging import get_logger

_FLAGS_WITH_VALUE = {"-p", "--param", "-r", "--remap", "--params-file", "--log-level", "-e", "--enclave",
                     "--log-config-file", "--log-file-name"}
_LOG_LEVELS = {"unset": 0, "debug": 10, "info": 20, "warn": 30, "warning": 30, "error": 40, "fatal": 50}


class RCLInvalidROSArgsError(RCLError):
    """rcl refuses a ROS argument outside rclpy.init: a node's own ``cli_args``, remove_ros_args (real rclpy's C
    extension defines it)."""

    __module__ = "rclpy._rclpy_pybind11"


# How rclpy words an rcl refusal of the command line: at rclpy.init, and elsewhere (Node's cli_args, remove_ros_args).
_GLOBAL = "failed to initialize rcl: "
_LOCAL = "Failed to parse ROS arguments: "
_ARGUMENTS_C = "/project/src/rcl/arguments.c"
_LEXER_C = "/project/src/rcl/lexer_lookahead.c"
# rcl's lexeme kinds (rcl/lexer.h), as its errors number them.
_NONE, _EOF, _TILDE_SLASH, _URL_SERVICE, _URL_TOPIC, _COLON = 0, 1, 2, 3, 4, 5
_NODE, _NS, _SEPARATOR, _TOKEN, _SLASH, _WILD_ONE, _WILD_MULTI, _DOT = 6, 7, 8, 18, 19, 20, 21, 22
# What rcl calls each flag's value in its refusal, and where it words it.
_KINDS = {"-p": ("parameter override rule", 352), "--param": ("parameter override rule", 352),
          "--params-file": ("params file", 415), "-r": ("remap rule", 380), "--remap": ("remap rule", 380),
          "--log-level": ("log level", 441)}
# What rcl says of each flag given last, with nothing after it, and where.
_TRAILING = {"-p": ("No parameter override rule found.", 356), "--param": ("No parameter override rule found.", 356),
             "-r": ("No remap rule found.", 384), "--remap": ("No remap rule found.", 384),
             "--params-file": ("No file path provided.", 419), "--log-file-name": ("No string prefix provided.", 480),
             "--log-config-file": ("No file path provided.", 515), "-e": ("No enclave path provided.", 550),
             "--enclave": ("No enclave path provided.", 550)}


@dataclass
class RosArgs:
    """What the ``--ros-args`` sections of a command line say. ``overrides`` holds its parameter files and ``-p``
    values in order; keys of ``remaps`` are (node name or '' for every node, name)."""

    overrides: ParamSet = field(default_factory=ParamSet)
    remaps: list[tuple[str, str, str]] = field(default_factory=list)  # (node or '', from, to)
    log_levels: dict[str, int] = field(default_factory=dict)  # logger name ('' = default) -> severity
    non_ros: list[str] = field(default_factory=list)

    @property
    def params(self) -> dict[tuple[str, str], object]:
        """Every value set, by (node key, or '' for every node, name)."""
        return {("" if node == "/**" else node, param.name): param.value()
                for node, params in self.overrides.nodes.items() for param in params}


def parse_scalar(text: str):
    """A parameter value as rcl reads ``-p name:=text`` (None: an empty sequence, a parameter left unset)."""
    values = ParamSet()
    values.set_value("/**", "value", text)
    return values.for_node("/any")["value"]


def _node_scoped(rule: str) -> tuple[str, str, str] | None:
    """'node:from:=to' or 'from:=to' -> (node or '', from, to); None when it is neither."""
    lhs, sep, rhs = rule.partition(":=")
    if not sep or not lhs:
        return None
    node, colon, name = lhs.rpartition(":")
    return (node if colon else "", name, rhs)


class _Lexemes:
    """rcl's lexer over a ``-p`` rule, two lexemes ahead: (kind, text) from ``index`` on."""

    # rcl's lexer (rcl/src/rcl/lexer.c) as one pattern, longest lexeme first; a token has no '__' in it.
    _PATTERN = re.compile(r"(:=)|(:)|(\.)|(/)|(\*\*)|(\*)|(__(?:node|name))|(__ns)|(~/)|(rosservice://)|"
                          r"(rostopic://)|\\([1-9])|((?:[A-Za-z]|_(?!_))(?:[A-Za-z0-9]|_(?!_))*_?)")
    _KINDS = (_SEPARATOR, _COLON, _DOT, _SLASH, _WILD_MULTI, _WILD_ONE, _NODE, _NS, _TILDE_SLASH, _URL_SERVICE,
              _URL_TOPIC, 9, _TOKEN)

    def __init__(self, text: str) -> None:
        self.text, self.index = text, 0

    def peek(self, ahead: int = 0) -> tuple[int, str]:
        at = self.index
        for _ in range(ahead + 1):
            if at >= len(self.text):
                return _EOF, ""
            m = self._PATTERN.match(self.text, at)
            if m is None:
                return _NONE, ""
            kind, at = self._KINDS[m.lastindex - 1], m.end()
            if m.lastindex == 12:  # a back-reference \1 .. \9: kinds 9 .. 17
                kind += int(m.group(12)) - 1
        return kind, m.group()

    def accept(self) -> str:
        text = self.peek()[1]
        self.index += len(text)
        return text

    def expect(self, kind: int) -> None:
        got = self.peek()[0]
        if got in (_NONE, _EOF):
            raise ParamFileError(f"Expected lexeme type ({kind}) not found, search ended at index {self.index}",
                                 f"{_LEXER_C}:239")
        if got != kind:
            raise ParamFileError(f"Expected lexeme type {kind}, got {got} at index {self.index}", f"{_LEXER_C}:244")
        self.accept()

    def name_token(self) -> None:
        """A parameter name's part: tokens and slashes (rcl has no wildcards in parameter names)."""
        kind = self.peek()[0]
        if kind not in (_TOKEN, _SLASH):
            problem, line = {_WILD_ONE: ("Wildcard '*' is not implemented", 1319),
                             _WILD_MULTI: ("Wildcard '**' is not implemented", 1322)}.get(
                kind, ("Expecting token or wildcard", 1325))
            raise ParamFileError(problem, f"{_ARGUMENTS_C}:{line}")
        while self.peek()[0] in (_TOKEN, _SLASH):
            self.accept()


def _param_rule(rule: str) -> tuple[str, str, str]:
    """A ``-p`` rule as rcl reads it: (node, or '/**' for every node; name; the YAML text of its value)."""
    lexemes = _Lexemes(rule)
    node = "/**"
    if lexemes.peek()[0] == _TOKEN and lexemes.peek(1)[0] == _COLON:
        node = lexemes.accept()
        lexemes.accept()
    start = lexemes.index
    lexemes.name_token()
    while lexemes.peek()[0] != _SEPARATOR:
        lexemes.expect(_DOT)
        lexemes.name_token()
    name = rule[start:lexemes.index]
    lexemes.expect(_SEPARATOR)
    return node, name, rule[lexemes.index:]


def _deprecated_remap(arg: str) -> tuple[str, str, str] | None:
    """A ``from:=to`` outside ``--ros-args`` that rcl still takes as a remap rule (the ROS 1 form, which it warns
    of), as (node or '', from, to); None when rcl's remap grammar does not read it as one, and it stays the
    program's (``_rate:=0.4``: a number is no name)."""
    lex = _Lexemes(arg)

    def take(*kinds: int) -> bool:
        if lex.peek()[0] in kinds:
            lex.accept()
            return True
        return False

    def name() -> bool:  # token (/ token)*, after an optional ~/ or /
        take(_TILDE_SLASH, _SLASH)
        if not take(_TOKEN):
            return False
        while take(_SLASH):
            if not take(_TOKEN):
                return False
        return True

    node = ""
    if lex.peek()[0] == _TOKEN and lex.peek(1)[0] == _COLON:
        node = lex.accept()
        lex.accept()
    start = lex.index
    if take(_NODE):
        valid = take(_SEPARATOR) and take(_TOKEN)
    elif take(_NS):
        valid = take(_SEPARATOR) and take(_SLASH)
        while valid and take(_TOKEN, _SLASH):
            pass
    else:
        take(_URL_SERVICE, _URL_TOPIC)
        valid = name() and take(_SEPARATOR) and name()
    if not valid or lex.peek()[0] != _EOF:
        return None
    source, _, target = arg[start:].partition(":=")
    return node, source, target


def parse(argv: list[str], *, at_init: bool = True) -> RosArgs:
    """Split ``argv`` into ROS arguments (after ``--ros-args``, up to ``--``) and the rest, reading parameter files
    and ``-p`` values in order. A refused argument raises what rclpy raises, with rcl's text: RCLError at rclpy.init
    (``at_init``), RCLInvalidROSArgsError elsewhere (a node's own ``cli_args``, remove_ros_args)."""
    out = RosArgs()
    in_ros = False
    i = 0
    while i < len(argv):
        arg = argv[i]
        i += 1
        if arg == "--ros-args":
            in_ros = True
            continue
        if not in_ros:
            rule = _deprecated_remap(arg)
            if rule is None:
                out.non_ros.append(arg)
            else:
                get_logger("rcl").warn(f"Found remap rule '{arg}'. This syntax is deprecated. Use '--ros-args "
                                       f"--remap {arg}' instead.")
                out.remaps.append(rule)
            continue
        if arg == "--":
            in_ros = False
            continue
        if arg not in _FLAGS_WITH_VALUE:
            continue  # --enable-rosout-logs and the like change nothing here
        if i >= len(argv):
            raise _refused(_trailing(arg), at_init)
        value = argv[i]
        i += 1
        try:
            _apply(out, arg, value)
        except ParamFileError as exc:
            kind, line = _KINDS[arg]
            raise _refused(f"Couldn't parse {kind}: '{arg} {value}'. Error: {exc}, at {_ARGUMENTS_C}:{line}",
                           at_init) from None
    return out


def _apply(out: RosArgs, flag: str, value: str) -> None:
    """Take one flag's value into ``out``; ParamFileError with rcl's inner text when rcl would refuse it."""
    if flag in ("-p", "--param"):
        out.overrides.set_value(*_param_rule(value))
    elif flag == "--params-file":
        out.overrides.read_file(value)
    elif flag in ("-r", "--remap"):
        rule = _node_scoped(value)
        if rule is None:
            raise ParamFileError(f"Couldn't parse rule '{value}'", None)
        out.remaps.append(rule)
    elif flag == "--log-level":
        name, sep, level = value.rpartition(":=")
        level_value = _LOG_LEVELS.get(level.lower())
        if level_value is None:
            raise ParamFileError("Argument does not use a valid severity level", f"{_ARGUMENTS_C}:1858")
        out.log_levels[name if sep else ""] = level_value


def _trailing(flag: str) -> str:
    """rcl's text for a flag with nothing after it."""
    if flag == "--log-level":
        return f"Couldn't parse trailing log level flag: '{flag}'. No log level provided., at {_ARGUMENTS_C}:445"
    what, line = _TRAILING[flag]
    return f"Couldn't parse trailing {flag} flag. {what}, at {_ARGUMENTS_C}:{line}"


def _refused(text: str, at_init: bool) -> RCLError:
    """What rclpy raises for a command line rcl refuses; rcl_init logs its line on stderr first."""
    if not at_init:
        return RCLInvalidROSArgsError(_LOCAL + text)
    get_logger("rcl").error("Failed to parse global arguments")
    return RCLError(_GLOBAL + text)
