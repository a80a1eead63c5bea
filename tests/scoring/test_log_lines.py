"""Log lines: format with decimals, level, rate in sim time, values relative to the start pose, and the format spec."""
from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest
from scoring_synth import path, run

from grader.metrics import MetricError, OutputLine, RunData
from grader.metrics.log_lines import Params, compile_format, measure
from grader.rubric import RubricError, load_rubric

FORMAT = "x={x:.2f} [m], y={y:.2f} [m], yaw={yaw:.1f} [degrees]."
DRIVE = [(2 * math.pi / 0.2, 0.1, 0.2), (5.0, 0.0, 0.0)]
START = dict(x0=-2.0, y0=-0.5, yaw0=math.radians(170), t0=12.3)
Pose = tuple[float, float, float]


def _relative(x: float, y: float, yaw: float) -> Pose:
    x0, y0, yaw0 = START["x0"], START["y0"], START["yaw0"]
    dx, dy = x - x0, y - y0
    d = math.atan2(math.sin(yaw - yaw0), math.cos(yaw - yaw0))
    return math.cos(yaw0) * dx + math.sin(yaw0) * dy, -math.sin(yaw0) * dx + math.cos(yaw0) * dy, d


def _logged(report: Callable[[float, float, float], Pose] = _relative, text: str = FORMAT, period: float = 1.0,
            stream: str = "rosout", level: str | None = "INFO", degrees: bool = True) -> RunData:
    """A run of DRIVE from START whose node logs ``report(pose)`` every ``period`` s, also echoed on stdout."""
    traj = path(DRIVE, START["x0"], START["y0"], START["yaw0"], START["t0"])
    lines = []
    for t in np.arange(START["t0"] + 0.5, traj.t[-1], period):
        k = int(np.searchsorted(traj.t, t, "right")) - 1
        x, y, yaw = report(float(traj.x[k]), float(traj.y[k]), float(traj.yaw[k]))
        body = text.format(x=x, y=y, yaw=math.degrees(yaw) if degrees else yaw)
        lines.append(OutputLine(float(t), stream, body, level if stream == "rosout" else None))
        if stream == "rosout":
            lines.append(OutputLine(float(t), "stdout", f"[{level}] [1795250908.523113, {t:.6f}]: {body}"))
    return run(DRIVE, **START, lines=lines)


def test_relative_pose_logged_at_1_hz_with_the_format_and_level_scores_everything() -> None:
    m = measure(_logged(), Params(format=FORMAT, level="INFO"))
    assert m["stream"] == "rosout" and m["n_lines"] == 36
    assert m["format_fraction"] == 1.0 and m["level_fraction"] == 1.0
    assert m["rate_hz"] == pytest.approx(1.0)
    assert m["values_fraction"] == 1.0 and m["relative_frame"] == "start_frame"
    assert m["absolute_fraction"] < 0.1


def test_offset_without_rotation_is_also_relative_to_the_start() -> None:
    def offset(x: float, y: float, yaw: float) -> Pose:
        return x - START["x0"], y - START["y0"], math.atan2(math.sin(yaw - START["yaw0"]), math.cos(yaw - START["yaw0"]))

    m = measure(_logged(offset), Params(format=FORMAT))
    assert m["values_fraction"] == 1.0 and m["relative_frame"] == "offset"


def test_absolute_pose_is_not_plausible_and_is_recognised() -> None:
    m = measure(_logged(lambda x, y, yaw: (x, y, yaw)), Params(format=FORMAT))
    assert m["values_fraction"] < 0.1 and m["absolute_fraction"] == 1.0


def test_yaw_in_radians_is_recognised() -> None:
    m = measure(_logged(degrees=False), Params(format=FORMAT))
    assert m["values_fraction"] < 0.5 and m["other_unit_fraction"] == 1.0


def test_wrong_decimals_fail_the_format_but_not_the_values_or_rate() -> None:
    m = measure(_logged(text="x={x:.3f} [m], y={y:.3f} [m], yaw={yaw:.1f} [degrees]."), Params(format=FORMAT))
    assert m["format_fraction"] == 0.0 and m["values_fraction"] == 1.0 and m["rate_hz"] == pytest.approx(1.0)
    assert m["format_example"].startswith("x=") and "[degrees]." in m["format_example"]


def test_other_wording_is_still_read_as_the_pose() -> None:
    m = measure(_logged(text="X: {x:.2f} m  Y: {y:.2f} m  Yaw: {yaw:.1f} deg"), Params(format=FORMAT))
    assert m["n_lines"] == 36 and m["format_fraction"] == 0.0 and m["values_fraction"] == 1.0


def test_printed_lines_have_no_level() -> None:
    m = measure(_logged(stream="stdout"), Params(format=FORMAT, level="INFO"))
    assert m["stream"] == "stdout" and m["level_fraction"] == 0.0 and m["levels"] == "print"
    assert m["format_fraction"] == 1.0


def test_warn_level_is_not_info() -> None:
    m = measure(_logged(level="WARN"), Params(format=FORMAT, level="INFO"))
    assert m["level_fraction"] == 0.0 and m["levels"] == "WARN"


def test_rate_is_in_sim_time() -> None:
    assert measure(_logged(period=0.1), Params(format=FORMAT))["rate_hz"] == pytest.approx(10.0)
    assert measure(_logged(period=2.0), Params(format=FORMAT))["max_gap_s"] == pytest.approx(2.0)


def test_a_log_without_pose_lines_cannot_be_measured() -> None:
    with pytest.raises(MetricError, match="no line of the node's log"):
        measure(run(DRIVE, lines=[OutputLine(1.0, "rosout", "starting", "INFO")]), Params(format=FORMAT))


@pytest.mark.parametrize("line,matches", [
    ("x=0.12 [m], y=-0.34 [m], yaw=12.3 [degrees].", True),
    ("x=-0.00 [m], y=1.00 [m], yaw=-179.9 [degrees].", True),
    ("x=0.1 [m], y=-0.34 [m], yaw=12.3 [degrees].", False),
    ("x=0.12 [m], y=-0.34 [m], yaw=12 [degrees].", False),
    ("x=0.12 [m], y=-0.34 [m], yaw=12.3 [degrees]", False),
    ("x = 0.12 [m], y=-0.34 [m], yaw=12.3 [degrees].", False),
])
def test_exact_format_checks_text_and_decimals(line: str, matches: bool) -> None:
    assert bool(compile_format(FORMAT).exact.fullmatch(line)) is matches


@pytest.mark.parametrize("fmt,message", [
    ("x={x:.2f}, x={x:.2f}", "must be a unique name"),
    ("x={:.2f}", "must be a unique name"),
    ("x={x:5.2e}", "write decimals as .Nf"),
    ("no fields", "has no {field}"),
    ("x={x", "is malformed"),
])
def test_bad_formats_are_rejected_when_the_rubric_loads(tmp_path, fmt: str, message: str) -> None:
    rubric_file = tmp_path / "log_task.toml"
    rubric_file.write_text(f'''
id = "log_task"
title = "t"
robot = "turtlebot3_waffle"
[[nodes]]
script = "a.py"
[[scenarios]]
name = "nominal"
[[criteria]]
id = "log_format"
title = "t"
points = 1
metric = "log_lines"
quantity = "format_fraction"
params = {{ format = {fmt!r} }}
tolerance = {{ bounds = [1.0, 1.0] }}
''', encoding="utf-8")
    with pytest.raises(RubricError, match=message.replace("{", r"\{").replace("}", r"\}")):
        load_rubric(rubric_file)
