"""A service client judged by what it sent and what it said: the request fields its node's calls carried (set from
its parameters, say) against the rubric's, and whether its output reported the response it got back."""
from __future__ import annotations

import math
import re
from typing import Any

from pydantic import JsonValue

from grader.metrics.base import Measurement, Metric, MetricParams
from grader.metrics.run import RunData
from grader.metrics.service_responses import _matches, _plain


class Params(MetricParams):
    """The service called, the request fields each call must carry, and the response fields whose values the
    node's output must hold after the call."""

    service: str
    request: dict[str, JsonValue] = {}
    reported: list[str] = []
    tolerance: float = 1e-9


def _shown(value: Any) -> str:
    """A value as a node's log line would print it (f-string formatting)."""
    return str(_plain(value))


def _in_text(value: Any, text: str) -> bool:
    """Whether a line holds the value: text as it is, a number as a whole number (7 is not in 17 or 0.7)."""
    shown = _shown(value)
    if isinstance(value, str):
        return shown in text
    return re.search(rf"(?<![\w.]){re.escape(shown)}(?![\w]|\.\d)", text) is not None


def measure(run: RunData, params: Params) -> Measurement:
    """Each call's request against ``request`` (the first wrong field named); the first answered call's response
    fields in ``reported`` looked for in the node's lines from the call on."""
    calls = [c for c in run.service_calls if c.service == params.service]
    wrong = []
    for number, call in enumerate(calls, 1):
        for name, want in params.request.items():
            got = call.request.get(name)
            if name not in call.request or not _matches(got, want, params.tolerance):
                wrong.append(f"call {number}: {name} = {_plain(got)!r}, expected {want!r}")
                break
    answered = next((c for c in calls if c.response is not None), None)
    missing: list[str] = []
    if answered is not None:
        lines = [line.message()[1] for line in run.lines if line.t >= answered.t]
        missing = [name for name in params.reported
                   if not any(_in_text(answered.response.get(name), text) for text in lines)]
    never = f"no call to {params.service} reached the server"
    return {
        "n_calls": len(calls),
        "request_fraction": (len(calls) - len(wrong)) / len(calls) if calls else 0.0,
        "first_wrong_request": wrong[0] if wrong else ("" if calls else never),
        "response": "" if answered is None else ", ".join(
            f"{name}={_plain(answered.response.get(name))!r}" for name in params.reported),
        "reported_fraction": (len(params.reported) - len(missing)) / len(params.reported)
        if answered is not None and params.reported else (math.nan if params.reported else 1.0),
        "first_unreported": "" if not missing else
        f"{missing[0]} = {_plain(answered.response.get(missing[0]))!r} is in no line your node wrote after the call",
        "no_response": "" if answered is not None else (never if not calls else f"{params.service} never answered"),
    }


METRIC = Metric(
    name="service_client",
    params=Params,
    quantities=frozenset({"n_calls", "request_fraction", "first_wrong_request", "response", "reported_fraction",
                          "first_unreported", "no_response"}),
    measure=measure,
)
