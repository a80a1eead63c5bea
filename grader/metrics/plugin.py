"""Instructor metrics from a Python file beside a rubric (``metric = "my_metrics.py:spiral_score"``), checked on load.

A plugin follows the built-in contract: a pure function of the run's arrays (``RunData``) and its parameters that
returns named quantities. The ``@metric`` decorator declares those quantities and the parameters' defaults, so a
rubric that names an unknown quantity or parameter fails when it is loaded, not halfway through a class's grading.
"""
from __future__ import annotations

import hashlib
import importlib.util
import inspect
import numbers
import sys
import traceback
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from types import ModuleType
from typing import Any

import numpy as np
from pydantic import create_model

from grader.metrics.base import Measurement, Metric, MetricError, MetricParams
from grader.metrics.run import RunData

MeasureFn = Callable[[RunData, Any], Mapping[str, Any]]
_PARAM_TYPES = (bool, int, float, str)


class PluginError(Exception):
    """A plugin metric cannot be used: the file, the name or its declaration is wrong; the message says how."""


def metric(quantities: Iterable[str], params: Mapping[str, Any] | None = None,
           needs_shutdown: bool = False) -> Callable[[MeasureFn], Metric]:
    """Declare ``fn(run, params) -> {quantity: value}`` as a metric.

    ``params`` maps each parameter name to its default (a bool, int, float or str, or None for "no default
    value": then any number may be given); a rubric may set only these, with a value of the default's type.
    """
    names = frozenset(quantities)
    if not names or not all(isinstance(q, str) and q.isidentifier() for q in names):
        raise PluginError("@metric(quantities=...) needs at least one quantity name, each a Python identifier")
    fields: dict[str, Any] = {}
    for name, default in (params or {}).items():
        if not name.isidentifier():
            raise PluginError(f"@metric parameter {name!r} is not a Python identifier")
        if default is None:
            fields[name] = (float | None, None)
        elif isinstance(default, _PARAM_TYPES):
            fields[name] = (type(default), default)
        else:
            raise PluginError(f"@metric parameter {name!r}: default must be a bool, int, float, str or None, "
                              f"got {type(default).__name__}")

    def declare(fn: MeasureFn) -> Metric:
        if not callable(fn):
            raise PluginError("@metric decorates a function fn(run, params)")
        try:
            inspect.signature(fn).bind(None, None)
        except (TypeError, ValueError):
            raise PluginError(f"metric function {fn.__name__} must take two arguments (run, params)") from None
        model = create_model(f"{fn.__name__}_params", __base__=MetricParams, **fields)
        return Metric(name=fn.__name__, params=model, quantities=names,
                      measure=_checked(fn, names), needs_shutdown=needs_shutdown)

    return declare


def _checked(fn: MeasureFn, quantities: frozenset[str]) -> Callable[[RunData, MetricParams], Measurement]:
    """Run the instructor's function; its own bugs become a MetricError that names it, never a crash of the grader."""

    def measure(run: RunData, params: MetricParams) -> Measurement:
        try:
            result = fn(run, params)
        except MetricError:
            raise
        except Exception as exc:  # the plugin's bug: score this criterion 0 and say where, keep grading the rest
            where = traceback.extract_tb(exc.__traceback__)[-1]
            raise MetricError(f"the rubric's metric {fn.__name__} failed ({type(exc).__name__}: {exc}, "
                              f"{Path(where.filename).name} line {where.lineno})") from exc
        if not isinstance(result, Mapping):
            raise MetricError(f"the rubric's metric {fn.__name__} returned {type(result).__name__}, not a dict")
        missing = sorted(quantities - set(result))
        if missing:
            raise MetricError(f"the rubric's metric {fn.__name__} did not return {', '.join(missing)}")
        return {q: _value(result[q]) for q in quantities}

    return measure


def _value(v: Any) -> float | int | str | bool | None:
    """A quantity as a plain JSON-able value (numpy scalars become Python numbers)."""
    if v is None or isinstance(v, str):
        return v
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    if isinstance(v, numbers.Integral):
        return int(v)
    try:
        return float(v)
    except (TypeError, ValueError):
        return str(v)


def load_plugin(spec: str, base_dir: Path) -> Metric:
    """The metric ``"file.py:name"`` names, with the file taken relative to ``base_dir`` (the rubric's folder)."""
    file_part, sep, attr = spec.partition(":")
    if not sep or not file_part.endswith(".py") or not attr.isidentifier():
        raise PluginError(f"plugin metric {spec!r} must look like \"my_metrics.py:function_name\"")
    path = (base_dir / file_part).resolve()
    if not path.is_file():
        raise PluginError(f"plugin file {file_part!r} not found next to the rubric (looked for {path})")
    module = _import(path)
    if not hasattr(module, attr):
        found = sorted(n for n, v in vars(module).items() if isinstance(v, Metric))
        raise PluginError(f"{file_part} defines no {attr!r}; its metrics are: {', '.join(found) or 'none'}")
    value = getattr(module, attr)
    if not isinstance(value, Metric):
        raise PluginError(f"{file_part}:{attr} is not declared as a metric; put "
                          "@metric(quantities=[...]) from grader.metrics.plugin above the function")
    return value


def _import(path: Path) -> ModuleType:
    """Import the file once per process under a name of its own (two rubrics' my_metrics.py never collide)."""
    name = "rosgrade_plugin_" + hashlib.sha256(str(path).encode()).hexdigest()[:16]
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise PluginError(f"cannot import {path}")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses and typing look a class's module up while it executes
    try:
        spec.loader.exec_module(module)
    except PluginError as exc:
        del sys.modules[name]
        raise PluginError(f"{path.name}: {exc}") from None
    except Exception as exc:  # a syntax error or a crash at import is the instructor's to fix: say where
        del sys.modules[name]
        line = getattr(exc, "lineno", None) or next(
            (f.lineno for f in reversed(traceback.extract_tb(exc.__traceback__)) if f.filename == str(path)), None)
        raise PluginError(f"{path.name} line {line}: cannot be imported: {type(exc).__name__}: {exc}") from None
    return module
