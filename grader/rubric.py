"""Rubric models: one TOML file per task names the node to run, the scenarios and the criteria; validated here.

An instructor adds a task by writing a TOML file that uses the existing metrics (see ``rubrics/README.md``).
Every mistake is reported as ``file: field: what was expected`` before anything runs.
"""
from __future__ import annotations

import math
import os
import re
import string
import tomllib
from collections.abc import Iterable
from pathlib import Path
from typing import Any, Literal

from pydantic import (
    BaseModel, ConfigDict, Field, PrivateAttr, ValidationError, ValidationInfo, field_validator, model_validator,
)

from grader.metrics import METRICS, Metric, MetricParams
from grader.metrics.facts import FACTS
from grader.metrics.plugin import PluginError, load_plugin
from grader.report import Visibility
from grader.wording import tidy
from grader.tolerance import Sigmoid, ToleranceError, check
from grader.runtime.spec import Limits
from sim import Scenario as WorldScenario

RUBRICS_ENV = "ROSGRADE_RUBRICS"
DEFAULT_DIR = Path(__file__).resolve().parent.parent / "rubrics"  # the `rubrics` package next to `grader`
# Names every feedback template may use besides the metric's quantities and the run facts.
TEMPLATE_NAMES = frozenset({"measured", "lower", "upper", "expected", "scenario", "credit", "points", "score"})
_ID = r"^[a-z][a-z0-9_]*$"
GRADER_NODES = Path(__file__).resolve().parent / "nodes"  # the nodes the grader ships (grader_nodes)
PLUGIN_DIR = "plugin_dir"  # validation context key: the folder plugin metric files are resolved in


def resolve_metric(name: str, base_dir: Path | None) -> Metric:
    """A built-in metric by name, or ``"file.py:function"`` from a plugin file in ``base_dir``."""
    if ":" not in name and not name.endswith(".py"):
        if name not in METRICS:
            raise ValueError(f"unknown metric {name!r}; expected one of {', '.join(sorted(METRICS))} "
                             "or a plugin \"my_metrics.py:function\" beside the rubric")
        return METRICS[name]
    if base_dir is None:
        raise ValueError(f"plugin metric {name!r} can only be used in a rubric file (its folder holds the plugin)")
    try:
        return load_plugin(name, Path(base_dir))
    except PluginError as e:
        raise ValueError(str(e)) from None


class RubricError(Exception):
    """A rubric file is unreadable or invalid; says which file, which field and what was expected."""

    def __init__(self, file: str | Path, field: str, expected: str, more: list[str] | None = None) -> None:
        self.file, self.field, self.expected = str(file), field, expected
        lines = [f"{self.file}: {field}: {expected}", *(more or [])]
        super().__init__("\n".join(lines))


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Scenario(WorldScenario):
    """One run of the node: the world's scenario (``sim.Scenario``) plus a name and a description for feedback."""

    name: str = Field(pattern=_ID)
    description: str = ""
    stdin: str | None = None  # typed into every node of this run instead of the node's own `stdin`
    # What this run asks for (e.g. the distance its stdin types): metric parameters of the same name, for every
    # criterion whose metric takes them; they override the criterion's own `params` on this scenario.
    params: dict[str, Any] = {}
    # The student nodes' parameters in this run (MIT's wall follower tests vary side, distance and speed), given after
    # each node's own args as a course's test passes them: rospy `_name:=value`, rclpy `--ros-args -p name:=value`.
    # They are metric parameters of the same name too, under `params`, which override them.
    node_params: dict[str, str | bool | int | float] = {}


class Node(_Model):
    """The student's script to run: found by file name in the submission, then by each alias in turn."""

    script: str = Field(pattern=r"^[\w.-]+\.py$")
    aliases: list[str] = []
    args: list[str] = []
    # The node's parameters, written for the client library it uses, after `args`: rospy `_name:=value`, rclpy
    # `--ros-args -p name:=value` (a ROS 1 `_name:=value` would be a deprecated remap rule to rcl, warned of).
    params: dict[str, str | bool | int | float] = {}
    stdin: str | None = None
    remaps: dict[str, str] = {}
    namespace: str | None = None  # ROS_NAMESPACE


class GraderNode(_Model):
    """A node the grader ships (``grader/nodes/``), run confined beside the student's: the server a student's client
    calls, as the course's own node would be."""

    script: str = Field(pattern=r"^[\w.-]+\.py$")
    args: list[str] = []

    @field_validator("script")
    @classmethod
    def _shipped(cls, script: str) -> str:
        if not (GRADER_NODES / script).is_file():
            shipped = ", ".join(sorted(p.name for p in GRADER_NODES.glob("*.py")))
            raise ValueError(f"the grader ships no node {script}; it ships {shipped}")
        return script


class LaunchFile(_Model):
    """Start the task from the student's launch file, as ``roslaunch pkg FILE name:=value ...`` (a roslaunch XML file)
    or ``ros2 launch pkg FILE name:=value ...`` (a ROS 2 .launch.py, .launch.xml or .launch.yaml) would."""

    file: str = Field(pattern=r"^[\w.-]+\.launch(\.xml|\.py|\.ya?ml)?$")
    # The package the file is in, by package.xml's name; shell wildcards allowed ("com2009_team*": each team's own).
    package: str | None = Field(None, pattern=r"^[a-z0-9_*?\[\]]+$")
    aliases: list[str] = []
    args: dict[str, str] = {}
    # roslaunch refuses a script without `chmod +x`; true runs it with python3 anyway (and says so).
    allow_not_executable: bool = False
    stdin: str | None = None


class Tolerance(_Model):
    """How the measured value becomes credit: full inside ``bounds``, ``value_at_margin`` at ``margin`` outside."""

    bounds: tuple[float, float]
    margin: float = 0.0
    sigmoid: Sigmoid = "linear"
    value_at_margin: float = 0.0

    @model_validator(mode="after")
    def _consistent(self) -> Tolerance:
        try:
            check(self.bounds, self.margin, self.sigmoid, self.value_at_margin)
        except ToleranceError as e:
            raise ValueError(str(e)) from None
        return self


class Condition(_Model):
    """A test on one measured quantity; a hint applies when all its conditions hold."""

    quantity: str
    min: float | None = None
    max: float | None = None
    equals: bool | float | str | None = None
    contains: str | None = None

    @model_validator(mode="after")
    def _has_test(self) -> Condition:
        if self.min is None and self.max is None and self.equals is None and self.contains is None:
            raise ValueError("a condition needs at least one of min, max, equals, contains")
        return self

    def holds(self, values: dict[str, Any]) -> bool:
        """True when the quantity is present and passes every test given."""
        v = values.get(self.quantity)
        if v is None:
            return False
        if self.contains is not None and self.contains.lower() not in str(v).lower():
            return False
        if self.equals is not None and v != self.equals:
            return False
        if self.min is None and self.max is None:
            return True
        if isinstance(v, (str, bool)) or math.isnan(float(v)):
            return False
        lo = -math.inf if self.min is None else self.min
        hi = math.inf if self.max is None else self.max
        return lo <= float(v) <= hi


class Hint(_Model):
    """Feedback about a likely cause, added when its conditions hold (e.g. radius 1 m and v = w).

    ``instead``: the text replaces the verdict whatever the credit, for runs the usual words would misdescribe
    (a node that had exited by itself before Ctrl+C was not "at rest 0.00 s after Ctrl+C").
    """

    when: list[Condition] = Field(min_length=1)
    text: str
    instead: bool = False


class Part(_Model):
    """One more quantity of the criterion's metric, scored with its own tolerance; the criterion averages the parts."""

    quantity: str
    tolerance: Tolerance


class Feedback(_Model):
    """Templates for the verdict, filled with ``{name:.3f}``-style fields (quantities, ``measured``, ``expected``...)."""

    passed: str = "{measured} is within {expected}."
    partial: str | None = None  # default: the failed text
    failed: str = "measured {measured}, expected {expected}."


class Criterion(_Model):
    """One scored item: a metric's quantity, mapped to credit by a tolerance, over one or more scenarios."""

    id: str = Field(pattern=_ID)
    title: str
    points: float = Field(gt=0.0)
    metric: str
    quantity: str
    params: dict[str, Any] = {}
    scenarios: list[str] | None = None  # None: every scenario of the rubric
    combine: Literal["min", "mean"] = "min"
    tolerance: Tolerance
    parts: list[Part] = []  # more quantities: the credit is the mean of `quantity`'s and each part's
    expected: str = ""
    visibility: Visibility = "visible"
    feedback: Feedback = Feedback()
    hints: list[Hint] = []
    _params: MetricParams = PrivateAttr()
    _metric: Metric = PrivateAttr()

    @field_validator("metric")
    @classmethod
    def _known_metric(cls, v: str, info: ValidationInfo) -> str:
        resolve_metric(v, (info.context or {}).get(PLUGIN_DIR))  # reported at the field; kept by the check below
        return v

    @model_validator(mode="after")
    def _check_against_metric(self, info: ValidationInfo) -> Criterion:
        base_dir = (info.context or {}).get(PLUGIN_DIR)
        self._metric = metric = resolve_metric(self.metric, base_dir)
        try:
            self._params = metric.params.model_validate(self.params)
        except ValidationError as e:
            raise ValueError(f"params for metric {self.metric!r}: " + "; ".join(_brief(err) for err in e.errors()))
        for quantity in (self.quantity, *(p.quantity for p in self.parts)):
            if quantity not in metric.quantities:
                raise ValueError(
                    f"quantity {quantity!r} is not measured by {self.metric!r}; "
                    f"expected one of {', '.join(sorted(metric.quantities))}"
                )
        known = metric.reported | FACTS | TEMPLATE_NAMES
        texts = [self.feedback.passed, self.feedback.partial or "", self.feedback.failed, *(h.text for h in self.hints)]
        for text in texts:
            for name in _template_names(text):
                if name not in known:
                    raise ValueError(f"feedback field {{{name}}} is unknown; expected one of {', '.join(sorted(known))}")
        for hint in self.hints:
            for cond in hint.when:
                if cond.quantity not in metric.reported | FACTS:
                    raise ValueError(f"hint condition on unknown quantity {cond.quantity!r}")
        return self

    @property
    def metric_def(self) -> Metric:
        """The metric this criterion measures with: built in, or the plugin its rubric's folder provides."""
        return self._metric

    @property
    def metric_params(self) -> MetricParams:
        """The validated parameters for this criterion's metric."""
        return self._params

    def params_for(self, scenario: Scenario) -> MetricParams:
        """The metric's parameters on one scenario: the criterion's, overridden by the scenario's that it takes."""
        asked = {**scenario.node_params, **scenario.params}
        taken = {k: v for k, v in asked.items() if k in self._metric.params.model_fields}
        if not taken:
            return self._params
        return self._metric.params.model_validate({**self.params, **taken})

    @property
    def expected_text(self) -> str:
        """What the feedback calls the expected value: the rubric's words, else the bounds."""
        if self.expected:
            return self.expected
        lo, hi = self.tolerance.bounds
        return f"{lo:g}" if lo == hi else f"between {lo:g} and {hi:g}"


class Rubric(_Model):
    """A task: its id and title, the robot, the node(s) to run, the scenarios and the criteria."""

    id: str = Field(pattern=_ID)
    title: str
    description: str = ""
    robot: str
    nodes: list[Node] = []
    # the nodes the student's launch file starts; with `nodes` too, the launch file when the submission holds it, else
    # the nodes (one task marked both ways: COM2009's `ros2 launch com2009_teamXX task1.launch.py`, a rospy script)
    launch: LaunchFile | None = None
    grader_nodes: list[GraderNode] = []  # with `nodes`: the grader's own nodes, started after the student's
    scenarios: list[Scenario] = Field(min_length=1)
    criteria: list[Criterion] = Field(min_length=1)
    limits: Limits = Limits()  # resource limits for the student's node in every scenario
    _source: Path | None = PrivateAttr(default=None)

    @model_validator(mode="before")
    @classmethod
    def _apply_defaults(cls, data: Any) -> Any:
        """Fill each scenario from ``scenario_defaults`` (one level deep) and the rubric's robot."""
        if not isinstance(data, dict):
            return data
        data = dict(data)
        defaults = data.pop("scenario_defaults", {}) or {}
        scenarios = data.get("scenarios")
        if isinstance(defaults, dict) and isinstance(scenarios, list):
            merged = []
            for s in scenarios:
                if not isinstance(s, dict):
                    merged.append(s)
                    continue
                m = {"robot": data.get("robot"), **defaults}
                for k, v in s.items():
                    m[k] = {**m[k], **v} if isinstance(v, dict) and isinstance(m.get(k), dict) else v
                merged.append(m)
            data["scenarios"] = merged
        return data

    @model_validator(mode="after")
    def _cross_references(self) -> Rubric:
        if not self.nodes and self.launch is None:
            raise ValueError("a rubric names the node(s) to run in [[nodes]] or a launch file in [launch]: "
                             "give at least one of them")
        if self.grader_nodes and (self.launch is not None or not self.nodes):
            raise ValueError("grader_nodes run beside the student's [[nodes]]; a launch file starts its own")
        names = [s.name for s in self.scenarios]
        _unique(names, "scenario name")
        _unique([c.id for c in self.criteria], "criterion id")
        by_name = {s.name: s for s in self.scenarios}
        for c in self.criteria:
            for name in c.scenarios or []:
                if name not in by_name:
                    raise ValueError(f"criterion {c.id!r} names scenario {name!r}; expected one of {', '.join(names)}")
            for s in self.scenario_list(c):
                try:
                    c.params_for(s)
                except ValidationError as e:
                    raise ValueError(f"scenario {s.name!r}: params for criterion {c.id!r}: "
                                     + "; ".join(_brief(err) for err in e.errors())) from None
            if c.metric_def.needs_shutdown:
                for s in self.scenario_list(c):
                    if s.shutdown_at is None:
                        raise ValueError(f"criterion {c.id!r} checks the shutdown, but scenario {s.name!r} has no shutdown_at")
        for s in self.scenarios:
            unused = set(s.params) - {k for c in self.criteria if c.scenarios is None or s.name in c.scenarios
                                      for k in c.metric_def.params.model_fields}
            if unused:
                raise ValueError(f"scenario {s.name!r}: params {', '.join(sorted(unused))} are taken by no metric of "
                                 "its criteria; check the spelling")
        return self

    @property
    def source(self) -> Path | None:
        """The TOML file this rubric was read from (None when built in code)."""
        return self._source

    @property
    def max_score(self) -> float:
        """Sum of the criteria's points."""
        return float(sum(c.points for c in self.criteria))

    def restricted_to(self, scenario_names: Iterable[str]) -> Rubric:
        """This rubric on the named scenarios only (re-scoring a subset of recordings, or a bag from a real robot);
        criteria that are scored on none of them are left out."""
        names = set(scenario_names)
        criteria = [c.model_copy(update={"scenarios": None if c.scenarios is None else
                                         [s for s in c.scenarios if s in names]})
                    for c in self.criteria if c.scenarios is None or names & set(c.scenarios)]
        return self.model_copy(update={"scenarios": [s for s in self.scenarios if s.name in names],
                                       "criteria": criteria})

    def scenario_list(self, criterion: Criterion) -> list[Scenario]:
        """The scenarios a criterion is scored on, in rubric order."""
        return [s for s in self.scenarios if criterion.scenarios is None or s.name in criterion.scenarios]


def _unique(values: list[str], what: str) -> None:
    seen: set[str] = set()
    for v in values:
        if v in seen:
            raise ValueError(f"{what} {v!r} appears twice; expected unique values")
        seen.add(v)


def _template_names(text: str) -> list[str]:
    """The field names a ``str.format`` template uses."""
    try:
        return [name.split(".")[0].split("[")[0] for _, name, _, _ in string.Formatter().parse(text) if name]
    except ValueError as e:
        raise ValueError(f"feedback template {text!r} is malformed: {e}") from None


def _brief(err: Any) -> str:
    """One pydantic error as 'field: message'."""
    loc = ".".join(str(p) for p in err["loc"])
    msg = str(err["msg"]).removeprefix("Value error, ")
    return f"{loc}: {msg}" if loc else msg


def _field_path(loc: tuple[Any, ...], data: Any) -> str:
    """``criteria[2] (id 'radius').tolerance.margin`` from a pydantic location and the raw data."""
    parts: list[str] = []
    node = data
    for p in loc:
        if isinstance(p, int):
            parts[-1] += f"[{p}]"
            node = node[p] if isinstance(node, list) and p < len(node) else None
            if isinstance(node, dict) and isinstance(node.get("id") or node.get("name"), str):
                parts[-1] += f" ({node.get('id') or node.get('name')!r})"
        else:
            parts.append(str(p))
            node = node.get(p) if isinstance(node, dict) else None
    return ".".join(parts) or "(top level)"


class SafeFormatter(string.Formatter):
    """``str.format`` that never fails on a value: a spec that does not fit (None with ``.3f``) prints the value."""

    def format_field(self, value: Any, format_spec: str) -> str:
        if isinstance(value, float) and math.isnan(value):
            return "n/a"
        try:
            return super().format_field(value, format_spec)
        except (ValueError, TypeError):
            return str(value)


def render(template: str, values: dict[str, Any]) -> str:
    """Fill a feedback template (unknown or missing fields print as 'n/a') and tidy its wording."""
    return tidy(SafeFormatter().vformat(template, (), _Missing(values)))


class _Missing(dict):  # type: ignore[type-arg]
    def __missing__(self, key: str) -> str:
        return "n/a"


def load_rubric(path: str | Path) -> Rubric:
    """Read and validate one rubric TOML file; raise RubricError naming the file, field and expectation."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as e:
        raise RubricError(path, "(file)", f"cannot read the rubric: {e.strerror or e}") from None
    except tomllib.TOMLDecodeError as e:
        where = re.search(r"line \d+(, column \d+)?", str(e))
        raise RubricError(path, where.group(0) if where else "(syntax)", f"TOML syntax error: {e}") from None
    try:
        rubric = Rubric.model_validate(data, context={PLUGIN_DIR: path.resolve().parent})
    except ValidationError as e:
        errors = e.errors()
        described = [(_field_path(tuple(err["loc"]), data), _describe(err)) for err in errors]
        first_field, first_msg = described[0]
        raise RubricError(path, first_field, first_msg, [f"{path}: {f}: {m}" for f, m in described[1:]]) from None
    if rubric.id != path.stem:
        raise RubricError(path, "id", f"the task id {rubric.id!r} must match the file name {path.stem!r}")
    rubric._source = path
    return rubric


def _describe(err: Any) -> str:
    """What was expected, in words, with the value given when it is short."""
    msg = str(err["msg"]).removeprefix("Value error, ")
    if err["type"] == "missing":
        return "required field is missing"
    if err["type"] == "extra_forbidden":
        return "unknown field (check the spelling; see rubrics/README.md for the fields)"
    given = err.get("input")
    if isinstance(given, (int, float, str, bool)) and len(repr(given)) < 60 and err["type"] not in ("value_error",):
        return f"{msg} (got {given!r})"
    return msg


def load_rubrics(directory: Path | None = None) -> dict[str, Rubric]:
    """Every ``*.toml`` rubric in ``directory`` (default: $ROSGRADE_RUBRICS, else the ``rubrics`` package), by id."""
    directory = Path(directory or os.environ.get(RUBRICS_ENV) or DEFAULT_DIR)
    if not directory.is_dir():
        raise RubricError(directory, "(directory)", "expected a directory of rubric TOML files")
    rubrics: dict[str, Rubric] = {}
    for path in sorted(directory.glob("*.toml")):
        rubric = load_rubric(path)
        rubrics[rubric.id] = rubric
    return rubrics


def task_table(extra: Iterable[str | Path] = (), builtin: bool = True) -> dict[str, Rubric]:
    """The tasks to grade by id: the built-in rubrics (``load_rubrics()``) plus every extra rubric file or folder.

    A folder contributes each ``*.toml`` in it; plugin metrics are found beside each file. A task id defined twice
    (an extra rubric named like a built-in one, or two extras) is a RubricError naming both files.
    Rubrics hold plugin functions, so a worker process should call this again rather than receive them pickled.
    """
    table = load_rubrics() if builtin else {}
    for entry in extra:
        entry = Path(entry)
        if entry.is_dir():
            found = list(load_rubrics(entry).values())
            if not found:
                raise RubricError(entry, "(directory)", "holds no *.toml rubric files")
        elif entry.suffix == ".toml" or not entry.exists():
            found = [load_rubric(entry)]
        else:
            raise RubricError(entry, "(file)", "expected a rubric .toml file or a folder of them")
        for rubric in found:
            if rubric.id in table:
                other = table[rubric.id].source or "a built-in rubric"
                raise RubricError(rubric.source or entry, "id", f"task {rubric.id!r} is already defined by {other}; "
                                  "give this task another id (and rename its file to match)")
            table[rubric.id] = rubric
    return table
