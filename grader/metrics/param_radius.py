"""A circle whose radius is a node parameter set at run time: the path is cut at each of the grader's ``ros2 param
set`` calls (its recorded SetParameters requests) and a circle is fitted to each stretch, which should have the
radius then in force."""
from __future__ import annotations

import math
from typing import Any

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.circle import fit_circle
from grader.metrics.motion import first_motion, path_length
from grader.metrics.run import RunData

# rcl_interfaces/msg/ParameterValue's field for each numeric ParameterType (what the grader may set a radius to)
_NUMBER_FIELDS = {2: "integer_value", 3: "double_value"}


class Params(TrajectoryParams):
    """The node and its parameter, the value it starts with, and the values the scenario sets, in order."""

    node: str = "/param_circle"
    name: str = "radius"
    initial: float
    values: list[float] = []
    settle_s: float = 2.0  # skip after each change: the robot turns from one circle onto the next
    min_path: float = 0.2  # m of driving a stretch needs before its circle means anything


def _sets(run: RunData, params: Params) -> list[tuple[float, float, Any]]:
    """(time, value, result) of each set of the parameter the grader made; result is the node's SetParametersResult,
    or None when the call was never answered."""
    service = f"{params.node.rstrip('/')}/set_parameters"
    sets = []
    for call in run.service_calls:
        if call.service != service:
            continue
        results = list(call.response["results"]) if call.response is not None else []
        for index, parameter in enumerate(call.request.get("parameters", [])):
            field = _NUMBER_FIELDS.get(int(parameter.value.type))
            if parameter.name == params.name and field is not None:
                sets.append((call.t, float(getattr(parameter.value, field)),
                             results[index] if index < len(results) else None))
    return sets


def measure(run: RunData, params: Params) -> Measurement:
    """Fit a circle to each stretch (first motion to the first set, set to set, the last set to Ctrl+C) and compare
    its radius with the value the grader had set; name the stretch furthest off and why it may be."""
    node, name = params.node.rstrip("/"), params.name
    sets = _sets(run, params)
    if len(sets) < len(params.values):
        missing = f"The grader's `ros2 param set {node} {name} {params.values[len(sets)]}` never reached your node"
        ended = run.run.ended_s
        if ended is not None and ended < (run.shutdown_time() or math.inf):
            raise MetricError(f"{missing}: it had ended by then ({ended - run.start_time:.1f} s after the start)")
        raise MetricError(
            f"{missing}: nothing served {node}/set_parameters. Name the node '{node.lstrip('/')}' "
            f"(super().__init__(\"{node.lstrip('/')}\")) and keep it spinning")
    traj = run.trajectory(params.source)
    started = first_motion(traj, params.rest_speed, params.rest_turn_rate)
    end = run.shutdown_time() or math.inf
    if started is None:
        raise MetricError("the robot never moved, so there is no circle to measure")
    bounds = [started] + [t for t, _, _ in sets] + [min(end, float(traj.t[-1]))]
    wanted = [params.initial] + [value for _, value, _ in sets]
    radii, errors, stuck = [], [], 0
    for k, want in enumerate(wanted):
        window = traj.between(bounds[k] + (params.settle_s if k else 1.0), bounds[k + 1])
        if path_length(window) < params.min_path:
            raise MetricError(f"the robot drove only {path_length(window):.2f} m between "
                              f"{bounds[k] - run.start_time:.1f} s and {bounds[k + 1] - run.start_time:.1f} s "
                              f"(with {name} = {want:g}), so there is no circle to measure there")
        radius = fit_circle(window.x, window.y).radius
        errors.append(abs(radius - want) / want)
        # the circle before the change, not the one set: the change never reached the motion
        stuck += k > 0 and abs(radius - radii[k - 1]) < abs(radius - want)
        radii.append(radius)
    worst = max(range(len(wanted)), key=errors.__getitem__)
    refused = next((f"your node refused `{name} = {value:g}`: \"{result.reason}\"" for _, value, result in sets
                    if result is not None and not result.successful), "")
    return {
        "max_error_rel": errors[worst],
        "n_stretches": len(wanted),
        "n_sets": len(sets),
        "n_unanswered": sum(result is None for _, _, result in sets),
        "stuck": stuck,
        "refused": refused,
        "radii": ", ".join(f"{r:.2f}" for r in radii),
        "expected_radii": ", ".join(f"{w:.2f}" for w in wanted),
        "worst": (f"from {bounds[worst] - run.start_time:.1f} s to {bounds[worst + 1] - run.start_time:.1f} s, with "
                  f"{name} = {wanted[worst]:g}, the robot drove a circle of radius {radii[worst]:.2f} m"),
        "decided_at_s": bounds[-1] - run.start_time,
    }


METRIC = Metric(
    name="param_radius",
    params=Params,
    quantities=frozenset({"max_error_rel", "n_stretches", "n_sets", "n_unanswered", "stuck", "refused", "radii",
                          "expected_radii", "worst", "decided_at_s"}),
    measure=measure,
)
