"""Build genpy-style message and service classes from genpy._msgdefs at import time, with precompiled codecs.

Each class gets generated ``__init__``, ``serialize`` and ``deserialize`` functions: consecutive fixed-size fields
(through nested messages) are packed with one precompiled struct, so a Twist is a single ``pack`` call. Classes are
built once and cached, so a type is the same object whichever package or module it is reached through.
"""
from __future__ import annotations

import struct
import sys
import types
from collections.abc import Callable

from . import _msgdefs
from .message import DeserializationError, Message, SerializationError, _rosmsg_errors, numpy1_retry, struct_I
from .rostime import Duration, Time

try:  # CPython's own MD5: importing hashlib loads OpenSSL, a few ms of every node's start
    from _md5 import md5 as _md5
except ImportError:  # an interpreter built without it
    from hashlib import md5 as _md5

_CODES = {"int8": "b", "uint8": "B", "byte": "b", "char": "B", "bool": "B", "int16": "h", "uint16": "H",
          "int32": "i", "uint32": "I", "int64": "q", "uint64": "Q", "float32": "f", "float64": "d"}
_TIMES = {"time": ("II", Time), "duration": ("ii", Duration)}
_BUILTINS = set(_CODES) | set(_TIMES) | {"string"}
_SEPARATOR = "=" * 80 + "\n"


class _Field:
    """One parsed field: name, full type text, base type, and array length (None: variable, -1: not an array)."""

    __slots__ = ("name", "type", "base", "length")

    def __init__(self, name: str, type_: str) -> None:
        self.name = name
        self.type = type_
        base, bracket, rest = type_.partition("[")
        self.base = base
        self.length = -1 if not bracket else (int(rest[:-1]) if rest[:-1] else None)

    @property
    def is_array(self) -> bool:
        return self.length != -1


class _Spec:
    """A parsed definition: constants (type, name, value text) and fields."""

    def __init__(self, full_name: str, text: str) -> None:
        self.full_name = full_name
        self.package = full_name.split("/")[0]
        self.constants: list[tuple[str, str, str]] = []
        self.fields: list[_Field] = []
        for line in text.splitlines():
            line = line.strip()
            if not line:
                continue
            type_, _, rest = line.partition(" ")
            type_ = self._resolve(type_)
            if "=" in rest:
                name, _, value = rest.partition("=")
                self.constants.append((type_, name.strip(), value.strip()))
            else:
                self.fields.append(_Field(rest.strip(), type_))

    def _resolve(self, type_: str) -> str:
        base, bracket, rest = type_.partition("[")
        if base == "Header":
            base = "std_msgs/Header"
        elif base not in _BUILTINS and "/" not in base:
            base = "%s/%s" % (self.package, base)
        return base + bracket + rest

    def text(self) -> str:
        """The normalised definition: constants, then fields, one per line, fully qualified type names."""
        lines = ["%s %s=%s" % c for c in self.constants] + ["%s %s" % (f.type, f.name) for f in self.fields]
        return "".join(line + "\n" for line in lines)

    def dependencies(self) -> list[str]:
        return [f.base for f in self.fields if f.base not in _BUILTINS]


def _md5_text(spec: _Spec) -> str:
    """The text ROS hashes: constants, then fields with nested types replaced by their md5."""
    lines = ["%s %s=%s" % c for c in spec.constants]
    for f in spec.fields:
        lines.append("%s %s" % (f.type if f.base in _BUILTINS else message_class(f.base)._md5sum, f.name))
    return "\n".join(lines)


def _full_text(spec: _Spec) -> str:
    """The concatenated definition: this type's text, then each dependency once, depth first."""
    seen: list[str] = []

    def visit(name: str) -> None:
        for dep in _specs[name].dependencies():
            if dep not in seen:
                seen.append(dep)
                visit(dep)

    visit(spec.full_name)
    return spec.text() + "".join("%sMSG: %s\n%s" % (_SEPARATOR, d, _specs[d].text()) for d in seen)


def _constant_value(type_: str, value: str):
    if type_ == "string":
        return value
    if type_ in ("float32", "float64"):
        return float(value)
    if type_ == "bool":
        return bool(int(value))
    return int(value)


# --- code generation -------------------------------------------------------------------------------------------

class _Codegen:
    """Writes the body of one generated function; collects the structs and classes it refers to."""

    def __init__(self, namespace: dict) -> None:
        self.namespace = namespace
        self.lines: list[str] = []
        self.depth = 1
        self.fmt = ""
        self.targets: list[str] = []
        self.after: list[str] = []

    def line(self, text: str) -> None:
        self.lines.append("    " * self.depth + text)

    def struct(self, fmt: str) -> str:
        name = "_S_" + fmt.replace("<", "")
        self.namespace.setdefault(name, struct.Struct(fmt))
        return name

    def cls(self, obj: type) -> str:
        name = "_C_" + obj._type.replace("/", "_")
        self.namespace[name] = obj
        return name


class _SerializeGen(_Codegen):
    """Generates ``serialize``: genpy's byte layout, with ``_x`` naming what was being written for error texts."""

    def flush(self) -> None:
        if self.fmt:
            self.line("buff.write(%s.pack(%s))" % (self.struct("<" + self.fmt), ", ".join(self.targets)))
            self.fmt, self.targets = "", []

    def value(self, expr: str, type_: str) -> None:
        if type_ in _CODES:
            if not self.fmt:
                self.line("_x = self")
            self.fmt += _CODES[type_]
            self.targets.append(expr)
        elif type_ in _TIMES:
            if not self.fmt:
                self.line("_x = self")
            self.fmt += _TIMES[type_][0]
            self.targets += [expr + ".secs", expr + ".nsecs"]
        elif type_ == "string":
            self.flush()
            self.line("_x = %s" % expr)
            self.line("_n = len(_x)")  # before encode: non-strings fail here with TypeError, as in genpy
            self.line("_x = _x.encode('utf-8')")
            self.line("buff.write(_S_I.pack(len(_x)))")
            self.line("buff.write(_x)")
        else:
            for f in message_class(type_)._spec.fields:
                self.field("%s.%s" % (expr, f.name), f)

    def field(self, expr: str, f: _Field) -> None:
        if not f.is_array:
            self.value(expr, f.type)
            return
        self.flush()
        prefix = "_n, " if f.length is None else ""
        if f.base in ("uint8", "char"):
            self.line("_x = %s" % expr)
            count = "_n" if f.length is None else str(f.length)
            fmt = "'<%s%%d%%s' %% (%s, 'B' if type(_x) in (list, tuple) else 's')" % (
                "I" if f.length is None else "", count)
            if f.length is None:
                self.line("_n = len(_x)")
            self.line("if type(_x) in (list, tuple):")
            self.line("    buff.write(struct.pack(%s, %s*_x))" % (fmt, prefix))
            self.line("else:")
            self.line("    buff.write(struct.pack(%s, %s_x))" % (fmt, prefix))
            return
        if f.length is None:
            self.line("_n = len(%s)" % expr)
            self.line("buff.write(_S_I.pack(_n))")
        if f.base in _CODES:
            fmt = "'<%%d%s' %% _n" % _CODES[f.base] if f.length is None else self.struct(
                "<%d%s" % (f.length, _CODES[f.base]))
            self.line(("buff.write(struct.pack(%s, *%s))" if f.length is None else "buff.write(%s.pack(*%s))")
                      % (fmt, expr))
            return
        var = "_v%d" % self.depth
        self.line("for %s in %s:" % (var, expr))
        self.depth += 1
        self.value(var, f.base)
        self.flush()
        self.depth -= 1


class _DeserializeGen(_Codegen):
    """Generates ``deserialize``: reads with one unpack per run of fixed-size fields, then fixes bools and times."""

    def flush(self) -> None:
        if self.fmt:
            name = self.struct("<" + self.fmt)
            self.line("_p = _e")
            self.line("_e += %d" % self.namespace[name].size)
            self.line("(%s,) = %s.unpack(_s[_p:_e])" % (", ".join(self.targets), name))
            for text in self.after:
                self.line(text)
            self.fmt, self.targets, self.after = "", [], []

    def read_length(self, target: str = "_n") -> None:
        self.line("_p = _e")
        self.line("_e += 4")
        self.line("(%s,) = _S_I.unpack(_s[_p:_e])" % target)

    def read_bytes(self, target: str, count: str) -> None:
        self.line("_p = _e")
        self.line("_e += %s" % count)
        self.line("%s = _s[_p:_e]" % target)

    def value(self, expr: str, type_: str) -> None:
        if type_ in _CODES:
            self.fmt += _CODES[type_]
            self.targets.append(expr)
            if type_ == "bool":
                self.after.append("%s = bool(%s)" % (expr, expr))
        elif type_ in _TIMES:
            self.fmt += _TIMES[type_][0]
            self.targets += [expr + ".secs", expr + ".nsecs"]
            self.after.append("%s.canon()" % expr)
        elif type_ == "string":
            self.flush()
            self.read_length()
            self.read_bytes("_b", "_n")
            self.line("%s = _b.decode('utf-8', 'rosmsg')" % expr)
        else:
            for f in message_class(type_)._spec.fields:
                self.field("%s.%s" % (expr, f.name), f)

    def field(self, expr: str, f: _Field) -> None:
        if not f.is_array:
            self.value(expr, f.type)
            return
        self.flush()
        count = "_n"
        if f.length is None:
            self.read_length()
        else:
            self.line("_n = %d" % f.length)
        if f.base in ("uint8", "char"):
            self.read_bytes(expr, count)
        elif f.base in _CODES:
            self.line("_p = _e")
            self.line("_e += struct.calcsize('<%%d%s' %% _n)" % _CODES[f.base])
            self.line("%s = struct.unpack('<%%d%s' %% _n, _s[_p:_e])" % (expr, _CODES[f.base]))
            if f.base == "bool":
                self.line("%s = list(map(bool, %s))" % (expr, expr))
        else:
            var = "_v%d" % self.depth
            self.line("%s = []" % expr)
            self.line("for _ in range(_n):")
            self.depth += 1
            if f.base == "string":
                self.value(var, "string")
            else:
                make = "_Time" if f.base == "time" else "_Duration" if f.base == "duration" else self.cls(
                    message_class(f.base))
                self.line("%s = %s()" % (var, make))
                self.value(var, f.base)
                self.flush()
            self.line("%s.append(%s)" % (expr, var))
            self.depth -= 1


def _default(gen: _Codegen, f: _Field) -> str:
    """Source of the expression giving a fresh default value for field f."""
    base = f.base
    if base in _CODES:
        scalar = "0.0" if base.startswith("float") else "False" if base == "bool" else "0"
    elif base == "string":
        scalar = "''"
    else:
        scalar = "%s()" % ("_Time" if base == "time" else "_Duration" if base == "duration"
                           else gen.cls(message_class(base)))
    if not f.is_array:
        return scalar
    if f.length is None:
        return "b''" if base in ("uint8", "char") else "[]"
    if base in ("uint8", "char"):
        return "b'\\0' * %d" % f.length
    if base in _CODES or base == "string":
        return "[%s] * %d" % ("0." if base.startswith("float") else scalar, f.length)
    return "[%s for _ in range(%d)]" % (scalar, f.length)


def _generate(cls: type, spec: _Spec) -> None:
    """Compile and attach __init__, serialize and deserialize for cls."""
    ns: dict = {"struct": struct, "_S_I": struct_I, "_Time": Time, "_Duration": Duration, "_Message": Message,
                "SerializationError": SerializationError, "DeserializationError": DeserializationError,
                "_rosmsg_errors": _rosmsg_errors, "_numpy1_retry": numpy1_retry}
    init = _Codegen(ns)
    init.line("if args or kwds:")
    init.line("    _Message.__init__(self, *args, **kwds)")
    for f in spec.fields:
        init.line("    if self.%s is None: self.%s = %s" % (f.name, f.name, _default(init, f)))
    init.line("else:")
    init.line("    pass" if not spec.fields else "    " + "; ".join(
        "self.%s = %s" % (f.name, _default(init, f)) for f in spec.fields))

    ser = _SerializeGen(ns)
    ser.depth = 2
    for f in spec.fields:
        ser.field("self." + f.name, f)
    ser.flush()
    error = ("self._check_types(SerializationError(\"%s: '%s' when writing '%s'\" % "
             "(type(_e), str(_e), str(locals().get('_x', self)))))")

    des = _DeserializeGen(ns)
    des.depth = 2
    if any(f.base == "string" for f in _all_fields(spec)):
        des.line("_rosmsg_errors.msg_type = self._type")
    for f in spec.fields:
        if not f.is_array and f.base not in _CODES and f.base != "string":
            des.line("if self.%s is None: self.%s = %s" % (f.name, f.name, _default(des, f)))
    des.line("_e = 0")
    for f in spec.fields:
        des.field("self." + f.name, f)
    des.flush()

    source = "\n".join([
        "def __init__(self, *args, **kwds):", *init.lines,
        "def serialize(self, buff):", "    _start = buff.tell()", "    try:", *(ser.lines or ["        pass"]),
        "    except (struct.error, TypeError) as _e:",
        "        if not _numpy1_retry(self, buff, _start):", "            " + error,
        "def deserialize(self, _s):", "    try:", *des.lines, "        return self",
        "    except struct.error as _e:", "        raise DeserializationError(_e)",
    ])
    exec(compile(source, "<genpy %s>" % spec.full_name, "exec"), ns)
    for name in ("__init__", "serialize", "deserialize"):
        func = ns[name]
        func.__qualname__ = "%s.%s" % (cls.__name__, name)
        setattr(cls, name, func)


def _all_fields(spec: _Spec):
    """Every field of spec and of the messages it contains."""
    for f in spec.fields:
        yield f
        if f.base not in _BUILTINS:
            yield from _all_fields(message_class(f.base)._spec)


# --- registry --------------------------------------------------------------------------------------------------

_specs: dict[str, _Spec] = {}
_classes: dict[str, type] = {}
_services: dict[str, type] = {}


def _spec(full_name: str, text: str) -> _Spec:
    spec = _specs.get(full_name)
    if spec is None:
        spec = _specs[full_name] = _Spec(full_name, text)
    return spec


def _make_class(full_name: str, text: str, module: str) -> type:
    spec = _spec(full_name, text)
    for dep in spec.dependencies():
        message_class(dep)
    name = full_name.split("/")[1]
    attrs = {
        "__slots__": [f.name for f in spec.fields], "__module__": module, "__qualname__": name,
        "__doc__": "Message class for %s (genpy semantics)." % full_name,
        "_type": full_name, "_md5sum": _md5(_md5_text(spec).encode()).hexdigest(),
        "_full_text": _full_text(spec), "_slot_types": [f.type for f in spec.fields],
        "_has_header": bool(spec.fields) and spec.fields[0].type == "std_msgs/Header"
        and spec.fields[0].name == "header", "_spec": spec,
    }
    attrs.update({c[1]: _constant_value(c[0], c[2]) for c in spec.constants})
    cls = type(name, (Message,), attrs)
    _classes[full_name] = cls
    _generate(cls, spec)
    return cls


def message_class(full_name: str) -> type:
    """The class of message type 'pkg/Name', building it (and its dependencies) on first use."""
    cls = _classes.get(full_name)
    if cls is None:
        if full_name not in _msgdefs.MESSAGES:
            raise KeyError("unknown message type %s" % full_name)
        pkg, name = full_name.split("/")
        cls = _make_class(full_name, _msgdefs.MESSAGES[full_name], "%s.msg._%s" % (pkg, name))
    return cls


def service_class(full_name: str) -> type:
    """The service class for 'pkg/Name', with _request_class and _response_class as genpy generates them."""
    cls = _services.get(full_name)
    if cls is None:
        pkg, name = full_name.split("/")
        module = "%s.srv._%s" % (pkg, name)
        request_text, _, response_text = _msgdefs.SERVICES[full_name].partition("---")
        request = _make_class(full_name + "Request", request_text, module)
        response = _make_class(full_name + "Response", response_text, module)
        md5 = _md5((_md5_text(request._spec) + _md5_text(response._spec)).encode()).hexdigest()
        cls = _services[full_name] = type(name, (object,), {
            "__module__": module, "__qualname__": name, "__doc__": "Service class for %s." % full_name,
            "_type": full_name, "_md5sum": md5, "_request_class": request, "_response_class": response})
    return cls


def _exports(package_module: str) -> dict[str, tuple[str, str]]:
    """Class name -> (what it is, its type) for a package module ('geometry_msgs.msg' or 'std_srvs.srv'), without
    building anything: "msg", or "srv"/"request"/"response" of a service."""
    pkg, kind = package_module.split(".")
    table: dict[str, tuple[str, str]] = {}
    if kind == "msg":
        for full_name in _msgdefs.MESSAGES:
            if full_name.startswith(pkg + "/"):
                table[full_name.split("/")[1]] = ("msg", full_name)
    else:
        for full_name in _msgdefs.SERVICES:
            if full_name.startswith(pkg + "/"):
                name = full_name.split("/")[1]
                table.update({name: ("srv", full_name), name + "Request": ("request", full_name),
                              name + "Response": ("response", full_name)})
    return table


def _resolve(what: str, full_name: str) -> type:
    if what == "msg":
        return message_class(full_name)
    srv = service_class(full_name)
    return {"srv": srv, "request": srv._request_class, "response": srv._response_class}[what]


def lazy_exports(package_module: str) -> tuple[Callable[[str], type], Callable[[], list[str]], list[str]]:
    """``(__getattr__, __dir__, __all__)`` for a package module: each class is built on first use (a node imports
    a package for one or two of its classes; building them all cost tens of milliseconds per node start), then kept
    in the module. Also registers genpy's ``<package_module>._Name`` submodules, equally lazy."""
    table = _exports(package_module)
    package = sys.modules[package_module]

    def module_getattr(name: str) -> type:
        try:
            what, full_name = table[name]
        except KeyError:
            raise AttributeError(f"module {package_module!r} has no attribute {name!r}") from None
        cls = _resolve(what, full_name)
        setattr(package, name, cls)
        return cls

    stems: dict[str, list[str]] = {}
    for name, (_, full_name) in table.items():
        stems.setdefault(full_name.split("/")[1], []).append(name)
    for stem, names in stems.items():
        module = types.ModuleType("%s._%s" % (package_module, stem))
        module.__getattr__ = _submodule_getattr(module, frozenset(names), module_getattr)  # type: ignore[method-assign]
        sys.modules.setdefault(module.__name__, module)
    names = sorted(table)
    return module_getattr, lambda: sorted(set(names) | set(vars(package))), names


def _submodule_getattr(module: types.ModuleType, names: frozenset[str],
                       package_getattr: Callable[[str], type]) -> Callable[[str], type]:
    def submodule_getattr(name: str) -> type:
        if name not in names:
            raise AttributeError(f"module {module.__name__!r} has no attribute {name!r}")
        cls = package_getattr(name)
        setattr(module, name, cls)
        return cls
    return submodule_getattr
