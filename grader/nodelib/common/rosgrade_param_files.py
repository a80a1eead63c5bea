"""ROS 2 parameter files and ``-p`` values read as rcl reads them, for the node (rclpy) and the grader (launch) alike.

rcl (rcl_yaml_param_parser) walks libyaml's events, not YAML's typed values: a key path names a node (``/ns/node``,
``node``, ``/**``, ``ns/*``), ``ros__parameters`` starts its parameters, nested keys join with '.', and each plain
scalar is typed by rcl's own rules (YAML 1.1 booleans, C ``strtoll``/``strtod`` numbers, anything else a string).
Every file and ``-p`` of one command line add to one table: a node entry keeps the place of its first appearance, a
value written again replaces the one of its type only, and rclpy reads the entries that match a node in that order.
PyYAML's event parser is libyaml's, ported; the node runs with the grader's interpreter, which has PyYAML (imported
only when there is something to read: a node without parameter files does not pay for it).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import yaml

PARAMS_KEY = "ros__parameters"
_STR_TAG = "tag:yaml.org,2002:str"
_TRUE = frozenset("Y y yes Yes YES true True TRUE on On ON".split())
_FALSE = frozenset("N n no No NO false False FALSE off Off OFF".split())
_SPECIAL_DOUBLES = {f"{sign}.{word}": float(sign + "inf") for sign in ("", "+", "-") for word in ("inf", "Inf", "INF")}
_SPECIAL_DOUBLES.update({f".{word}": float("nan") for word in ("nan", "NaN", "NAN")})
# What C's strtoll (base 0) and strtod read in full: leading white space, a sign, then the number.
_C_INT = re.compile(r"[ \t\n\v\f\r]*([+-]?)(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)")
_C_DEC = re.compile(r"[ \t\n\v\f\r]*[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
_C_HEX = re.compile(r"[ \t\n\v\f\r]*([+-]?)0[xX]((?:[0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)(?:[pP][+-]?[0-9]+)?)")
_C_WORD = re.compile(r"[ \t\n\v\f\r]*([+-]?)(inf|infinity|nan(?:\([0-9A-Za-z_]*\))?)", re.IGNORECASE)
_INT64 = 1 << 63
_DBL_MIN = 2.2250738585072014e-308
# The order rclpy looks at a value's slots in (_parameter_from_rcl_variant): the first one set is the value.
_SLOTS = ("bool", "integer", "double", "string", "bool_array", "integer_array", "double_array", "string_array")

# Where rcl (the Jazzy wheels' build) sets each error: its messages end with ", at <file>:<line>".
_PARSE_C = "/project/src/parse.c"
_PARSER_C = "/project/src/parser.c"
_SEQUENCE_LINE = {"bool": 309, "integer": 350, "double": 391, "string": 435}
_NODE_NAME_RULES = ((re.compile(r"[^A-Za-z0-9_]"), "node name must not contain characters other than alphanumerics or "
                     "'_'"), (re.compile(r"^[0-9]"), "node name must not start with a number"))


class ParamFileError(Exception):
    """A parameter file or ``-p`` value rcl refuses: ``problem`` is rcl's text, ``str()`` adds where rcl set it."""

    def __init__(self, problem: str, where: str | None) -> None:
        super().__init__(problem + (f", at {where}" if where else ""))
        self.problem = problem


def _fail(problem: str, line: int | None = None, source: str = _PARSE_C) -> ParamFileError:
    return ParamFileError(problem, f"{source}:{line}" if line is not None else None)


def typed_value(text: str, style: str | None = None, tag: str | None = None) -> tuple[str, object]:
    """(kind, value) of one YAML scalar as rcl types it: quoted or ``!!str`` is a string; otherwise a YAML 1.1
    boolean word, then a whole C integer (0x hex, leading-0 octal, within int64), then a whole C double, else text."""
    if tag == _STR_TAG:
        return "string", text
    if style in ("'", '"'):
        return "string", text
    if text in _TRUE:
        return "bool", True
    if text in _FALSE:
        return "bool", False
    if m := _C_INT.fullmatch(text):
        digits = m.group(2)
        magnitude = int(digits, 16) if digits[1:2] in ("x", "X") else int(digits, 8) if digits.startswith("0") \
            else int(digits)
        value = -magnitude if m.group(1) == "-" else magnitude
        if -_INT64 <= value < _INT64:
            return "integer", value
    if text in _SPECIAL_DOUBLES:
        return "double", _SPECIAL_DOUBLES[text]
    double = _c_double(text)
    if double is not None:
        return "double", double
    return "string", text


def _c_double(text: str) -> float | None:
    """What strtod reads from the whole of ``text``; None when it stops early or reports a range error."""
    if _C_DEC.fullmatch(text):
        value, mantissa = float(text.strip()), re.split("[eE]", text)[0]
    elif m := _C_HEX.fullmatch(text):
        mantissa = re.split("[pP]", m.group(2))[0]
        value = float.fromhex(m.group(1) + "0x" + (m.group(2) if mantissa != m.group(2) else m.group(2) + "p0"))
    elif m := _C_WORD.fullmatch(text):
        return float(m.group(1) + ("nan" if m.group(2).lower().startswith("nan") else "inf"))
    else:
        return None
    if math.isinf(value) or (abs(value) < _DBL_MIN and re.search("[1-9a-fA-F]", mantissa.strip().lstrip("+-"))):
        return None  # ERANGE: overflow, or underflow to a subnormal or zero
    return value


@dataclass
class _Param:
    """One parameter entry of a node entry: its name and the slots its values were written to."""

    name: str
    slots: dict[str, object] = field(default_factory=dict)

    def value(self) -> object:
        return next((self.slots[s] for s in _SLOTS if s in self.slots), None)


@dataclass
class _Walk:
    """Where the event walk is: rcl's parse state (key or value, in a sequence, map level and depth, name stacks)."""

    node: str | None = None
    node_count: int = 0
    param_ns: str | None = None
    param_count: int = 0
    level: int = 1  # 1: node names, 2: parameters
    depth: int = 0
    is_key: bool = True
    is_seq: bool = False
    seq_kind: str | None = None
    new_map: bool = False
    node_key: str | None = None
    param: _Param | None = None


def _push(current: str | None, count: int, name: str, sep: str) -> tuple[str, int]:
    if count == 0 or current is None:
        return name, count + 1
    return current + ("" if current.endswith(sep) else sep) + name, count + 1


def _pop(current: str | None, count: int, sep: str) -> tuple[str | None, int]:
    if count == 0:
        return current, 0
    if count == 1 or current is None:
        return None, 0
    cut = current.rfind(sep)
    return (current[:cut] if cut >= 0 else current), count - 1


class ParamSet:
    """The parameter overrides of one command line: node entries in order of first appearance, each with its
    parameters; files and ``-p`` values are added in the command line's order."""

    def __init__(self) -> None:
        self.nodes: dict[str, list[_Param]] = {}

    # -- reading ----------------------------------------------------------------------------------------------------
    def read_file(self, path: str) -> None:
        """Add a parameter file; ParamFileError with rcl's text when it cannot be opened or read."""
        try:
            with open(path, "rb") as f:
                data = f.read()
        except IsADirectoryError:  # C's fopen opens a folder; libyaml fails on its first read
            raise _fail("Error parsing a event near line 0", 782) from None
        except (OSError, ValueError):
            raise _fail("Error opening YAML file", 271, _PARSER_C) from None
        self.read_text(data)

    def read_text(self, text: str | bytes) -> None:
        """Add the contents of a parameter file."""
        import yaml
        walk = _Walk()
        line = 0
        events = yaml.parse(text, Loader=yaml.SafeLoader)
        while True:
            try:
                event = next(events)
            except StopIteration:
                return
            except yaml.YAMLError:
                raise _fail(f"Error parsing a event near line {line}", 782) from None
            line = event.start_mark.line + 1
            self._file_event(walk, event, line)

    def set_value(self, node: str, name: str, text: str) -> None:
        """Add one ``-p [node:]name:=text`` (node '/**' when unscoped); ParamFileError with rcl's text when refused
        (rcl sets none for an empty value: "error not set")."""
        if not node or not name or not text:
            raise ParamFileError("error not set", None)  # rcl returns without setting an error
        import yaml
        param = self._find_param(self._find_node(node), name)
        walk = _Walk(param=param, node_key=node)
        try:
            for event in yaml.parse(text, Loader=yaml.SafeLoader):
                if isinstance(event, yaml.ScalarEvent):
                    self._value(walk, event, event.start_mark.line + 1)
                elif isinstance(event, yaml.SequenceStartEvent):
                    walk.is_seq, walk.seq_kind = True, None
                elif isinstance(event, yaml.SequenceEndEvent):
                    walk.is_seq = False
                elif not isinstance(event, (yaml.StreamStartEvent, yaml.StreamEndEvent, yaml.DocumentStartEvent,
                                            yaml.DocumentEndEvent)):
                    raise _fail("Unknown YAML event", 965)
        except yaml.YAMLError:
            raise _fail("Error parsing an event", 935) from None

    # -- looking up -------------------------------------------------------------------------------------------------
    def for_node(self, fqn: str) -> dict[str, object]:
        """The overrides rclpy gives the node ``fqn``: every matching entry in order, later names replacing earlier;
        a value None is a parameter left unset (an empty sequence)."""
        out: dict[str, object] = {}
        for key, params in self.nodes.items():
            if node_key_matches(key, fqn):
                for param in params:
                    out[param.name] = param.value()
        return out

    # -- rcl's walk -------------------------------------------------------------------------------------------------
    def _file_event(self, walk: _Walk, event: yaml.Event, line: int) -> None:
        import yaml
        if isinstance(event, yaml.ScalarEvent):
            if walk.is_key:
                self._key(walk, event.value, line)
                walk.is_key = False
                return
            if walk.level < 2:
                raise _fail(f"Cannot have a value before {PARAMS_KEY} at line {line}", 806)
            if not self.nodes:
                raise _fail(f"Cannot have a value before {PARAMS_KEY} at line {line}", 812)
            if not self.nodes[walk.node_key]:
                raise _fail(f"Cannot have a value before {PARAMS_KEY} at line {line}", 818)
            self._value(walk, event, line)
            if not walk.is_seq:
                walk.is_key = True
        elif isinstance(event, yaml.SequenceStartEvent):
            if walk.is_key:
                raise _fail(f"Sequences cannot be key at line {line}", 835)
            if walk.level < 2:
                raise _fail(f"Sequences can only be values and not keys in params. Error at line {line}\n", 841)
            walk.is_seq, walk.seq_kind = True, None
        elif isinstance(event, yaml.SequenceEndEvent):
            walk.is_seq, walk.is_key = False, True
        elif isinstance(event, yaml.MappingStartEvent):
            walk.depth += 1
            walk.new_map = walk.is_key = True
            if walk.level == 2 and walk.depth - (walk.node_count + 1) == 2:
                walk.new_map = False
        elif isinstance(event, yaml.MappingEndEvent):
            if walk.level == 2:
                if walk.param_count > 0:
                    walk.param_ns, walk.param_count = _pop(walk.param_ns, walk.param_count, ".")
                else:
                    walk.level -= 1
            elif walk.depth == walk.node_count + 1:
                walk.node, walk.node_count = _pop(walk.node, walk.node_count, "/")
            walk.depth -= 1
        elif isinstance(event, yaml.AliasEvent):
            raise _fail(f"Will not support aliasing at line {line}\n", 893)

    def _key(self, walk: _Walk, key: str, line: int) -> None:
        if not key:
            raise _fail(f"No key at line {line}", 619)
        if walk.level == 1:
            if not key.startswith(PARAMS_KEY):
                walk.node, walk.node_count = _push(walk.node, walk.node_count, key, "/")
                return
            if walk.node_count == 0 or walk.node is None:
                raise _fail(f"There are no node names before {PARAMS_KEY} at line {line}", 642)
            check_node_key(walk.node)
            walk.node_key = self._find_node(walk.node)
            walk.node, walk.node_count = _pop(walk.node, walk.node_count, "/")
            walk.level = 2
            return
        params = self.nodes[walk.node_key]
        if walk.new_map:
            if walk.param is None or walk.param not in params:
                raise _fail(f"Internal error creating param namespace at line {line}", 687)
            walk.param_ns, walk.param_count = walk.param.name, walk.param_count + 1
            walk.new_map = False
        if walk.param_ns is None:
            walk.param = self._find_param(walk.node_key, key)
        else:
            walk.param = self._find_param(walk.node_key, walk.param_ns)
            walk.param.name = f"{walk.param_ns}.{key}"

    def _value(self, walk: _Walk, event: yaml.ScalarEvent, line: int) -> None:
        if event.style not in ("'", '"') and not event.value:
            raise _fail(f"No value at line {line}", 258)
        kind, value = typed_value(event.value, event.style, event.tag)
        slots = walk.param.slots
        if not walk.is_seq:
            slots[kind] = value
            return
        if walk.seq_kind is None:
            walk.seq_kind = kind
            slots[kind + "_array"] = []
        elif walk.seq_kind != kind:
            raise _fail(f"Sequence should be of same type. Value type '{kind}' do not belong at line_num {line}",
                        _SEQUENCE_LINE[kind])
        slots[kind + "_array"].append(value)

    def _find_node(self, name: str) -> str:
        self.nodes.setdefault(name, [])
        return name

    def _find_param(self, node: str, name: str) -> _Param:
        params = self.nodes[node]
        for param in params:
            if param.name == name:
                return param
        params.append(_Param(name))
        return params[-1]


def check_node_key(name: str) -> None:
    """rcl's check of a node key before ``ros__parameters``: each namespace token and the node name (``*``/``**``
    allowed in place of either); ParamFileError with rmw's text."""
    if name in ("/**", "/*"):
        return
    cut = name.rfind("/")
    node = name[cut + 1:]
    if cut >= 0:
        namespace = name[:cut + 1] if name.startswith("/") else "/" + name[:cut + 1]
        tokens = re.findall(r"/[^/]*", namespace[:-1]) if len(namespace) > 1 else ["/"]
        for token in tokens:
            if token == "/":
                if namespace != "/":
                    raise _fail(f"{namespace} contains repeated forward slash", 557)
            elif token not in ("/**", "/*"):
                _check_namespace_token(token)
    if node not in ("*", "**"):
        if not node:
            raise _fail("node name must not be empty", 490)
        for rule, text in _NODE_NAME_RULES:
            if rule.search(node):
                raise _fail(text, 490)
        if len(node) > 255:
            raise _fail("node name length should not exceed 255", 490)


def _check_namespace_token(token: str) -> None:
    if re.search(r"[^A-Za-z0-9_/]", token):
        raise _fail("namespace must not contain characters other than alphanumerics, '_', or '/'", 472)
    if token[1:2].isdigit():
        raise _fail("namespace must not have a token that starts with a number", 472)


def node_key_matches(key: str, fqn: str) -> bool:
    """Whether the node key of a parameter file names the node ``fqn`` as rclpy decides it: '/' put in front, each
    '/*' one namespace token, '/**' any number of them, the rest literal and whole."""
    pattern = "(/[A-Za-z0-9_]+)".join((key if key.startswith("/") else "/" + key).split("/*"))
    try:
        return re.fullmatch(pattern, fqn) is not None
    except re.error:
        return False
