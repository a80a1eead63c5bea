"""Service responses field by field: what a node's server answered to each call of a service (the scenario's own
``service_calls``, as ``ros2 service call`` makes them), against the fields the rubric expects."""
from __future__ import annotations

import math
from typing import Any

from pydantic import JsonValue

from grader.metrics.base import Measurement, Metric, MetricParams
from grader.metrics.run import RunData


class Params(MetricParams):
    """The service, and per call in order the response fields expected (a scenario sets them beside its calls);
    numbers match within ``tolerance``."""

    service: str
    expected: list[dict[str, JsonValue]] = []
    tolerance: float = 1e-9


def _matches(got: Any, want: Any, tolerance: float) -> bool:
    if isinstance(want, bool) or isinstance(got, bool):
        return type(got) is type(want) and got == want
    if isinstance(want, (int, float)) and isinstance(got, (int, float)):
        return math.isclose(float(got), float(want), rel_tol=0.0, abs_tol=tolerance) or got == want
    if isinstance(want, list) and hasattr(got, "__len__") and not isinstance(got, str):
        return len(got) == len(want) and all(_matches(g, w, tolerance) for g, w in zip(got, want))
    return got == want


def _plain(value: Any) -> Any:
    """A field's value as feedback shows it (arrays as lists)."""
    return value.tolist() if hasattr(value, "tolist") else value


def _request_text(request: dict[str, Any]) -> str:
    return ", ".join(f"{name}={_plain(value)!r}" for name, value in request.items())


def measure(run: RunData, params: Params) -> Measurement:
    """Pair each expected response with the service's calls in order; the first wrong field names call, field and
    value. A call with no response (the server failed it, or never answered before the run ended) counts as wrong."""
    calls = [c for c in run.service_calls if c.service == params.service]
    n_answered = sum(c.response is not None for c in calls)
    wrong: list[str] = []
    first: tuple[str, Any, Any] | None = None
    for index, want in enumerate(params.expected):
        if index >= len(calls):
            wrong.append(f"call {index + 1} to {params.service} was never made (the service was not offered, "
                         "or an earlier call was never answered)")
            continue
        call = calls[index]
        if call.response is None:
            wrong.append(f"call {index + 1} ({_request_text(call.request)}) got no response")
            continue
        for name, value in want.items():
            got = call.response.get(name)
            if name not in call.response or not _matches(got, value, params.tolerance):
                if first is None:
                    first = (name, _plain(got), value)
                wrong.append(f"call {index + 1} ({_request_text(call.request)}): {name} = {_plain(got)!r}, "
                             f"expected {value!r}")
                break
    n_expected = len(params.expected)
    return {
        "n_calls": len(calls),
        "n_answered": n_answered,
        "answered_fraction": n_answered / n_expected if n_expected else math.nan,
        "n_correct": n_expected - len(wrong),
        "correct_fraction": (n_expected - len(wrong)) / n_expected if n_expected else math.nan,
        "all_correct": not wrong and n_expected > 0,
        "first_wrong": wrong[0] if wrong else "",
        "wrong_field": first[0] if first else "",
        "wrong_value": repr(first[1]) if first else "",
        "expected_value": repr(first[2]) if first else "",
    }


METRIC = Metric(
    name="service_responses",
    params=Params,
    quantities=frozenset({"n_calls", "n_answered", "answered_fraction", "n_correct", "correct_fraction",
                          "all_correct", "first_wrong", "wrong_field", "wrong_value", "expected_value"}),
    measure=measure,
)
