"""Pose printing: parse realistic print formats, detect degrees or radians, compare with odometry across +-pi."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scoring_synth import path

from grader.metrics import OutputLine, RunData
from grader.metrics.pose_print import Params, measure, parse_pose

# Turn left through +180 degrees while creeping forward, as the odom_subscriber scenario does.
ODOM = path([(1.0, 0.0, 0.0), (6.0, 0.1, 0.5), (6.0, 0.1, -0.5)], yaw0=2.6, t0=25.0)


@pytest.mark.parametrize(
    "text, expected",
    [
        ("(x,y,θz) = (0.50, -0.20, 1.57)", (0.5, -0.2, 1.57)),
        ("[INFO] [1795250908.523113, 21.060000]: x = 0.50 [m], y = -0.20 [m], yaw = 90.0 [degrees].", (0.5, -0.2, 90.0)),
        ("x: 0.123, y: -4.5, theta: -3.14", (0.123, -4.5, -3.14)),
        ("Position X=1.0 Y=2.0 Heading=45.0°", (1.0, 2.0, 45.0)),
        ("pos_x = 1e-3, pos_y = 2, theta_z = 0.5", (0.001, 2.0, 0.5)),
        ("0.50 -0.20 1.57", (0.5, -0.2, 1.57)),
        ("[INFO] [12.5]: The 'odom_subscriber' node is active...", None),
        ("Robot X = 3.000000", None),
    ],
)
def test_parse_realistic_formats(text: str, expected: tuple[float, float, float] | None) -> None:
    assert parse_pose(text) == (pytest.approx(expected) if expected else None)


def _lines(fmt: str, yaw_of=lambda yaw: yaw, lag: int = 0, stream: str = "stdout", every: int = 3) -> list[OutputLine]:
    """Print each ``every``-th odometry sample, ``lag`` samples late, 2 ms after it arrives."""
    out = []
    for i in range(lag, len(ODOM), every):
        j = i - lag
        out.append(OutputLine(float(ODOM.t[i]) + 0.002, stream, fmt.format(ODOM.x[j], ODOM.y[j], yaw_of(ODOM.yaw[j]))))
    return out


def _measure(lines: list[OutputLine]) -> dict:
    return measure(RunData(odometry=ODOM, lines=tuple(lines), start_time=25.0), Params())


def test_radians_with_two_decimals_all_correct_across_pi() -> None:
    m = _measure(_lines("(x,y,θz) = ({:.2f}, {:.2f}, {:.2f})"))
    assert m["fraction_correct"] == 1.0 and m["yaw_unit"] == "radians"
    assert m["rate_hz"] == pytest.approx(10.0, abs=0.1)


def test_degrees_detected_from_the_numbers() -> None:
    m = _measure(_lines("[INFO] [1.0, 2.0]: x={:.2f} y={:.2f} yaw={:.1f}", yaw_of=math.degrees))
    assert m["fraction_correct"] == 1.0 and m["yaw_unit"] == "degrees"


def test_degrees_printed_in_0_to_360_are_still_right() -> None:
    m = _measure(_lines("x={:.3f} y={:.3f} yaw={:.1f} deg", yaw_of=lambda a: math.degrees(a) % 360.0))
    assert m["fraction_correct"] == 1.0


def test_one_odometry_period_of_latency_is_allowed() -> None:
    assert _measure(_lines("{:.3f} {:.3f} {:.3f}", lag=1))["fraction_correct"] == 1.0
    assert _measure(_lines("{:.3f} {:.3f} {:.3f}", lag=4))["fraction_correct"] < 0.5


def test_quaternion_z_printed_as_yaw_is_caught() -> None:
    m = _measure(_lines("x={:.3f} y={:.3f} yaw={:.3f}", yaw_of=lambda a: math.sin(a / 2.0)))
    assert m["fraction_correct"] < 0.2 and m["quaternion_z_fraction"] > 0.9


def test_unsigned_yaw_fails_after_crossing_pi() -> None:
    # 2*acos(w) loses the sign: right while yaw > 0, wrong once the robot has turned past +180 degrees.
    m = _measure(_lines("x={:.3f} y={:.3f} yaw={:.3f}", yaw_of=abs))
    assert 0.1 < m["fraction_correct"] < 0.5 and m["yaw_error_max_deg"] > 90


def test_loginfo_on_stdout_and_rosout_is_counted_once() -> None:
    lines = _lines("x={:.2f} y={:.2f} yaw={:.2f}") + _lines("x={:.2f} y={:.2f} yaw={:.2f}", stream="rosout")
    m = _measure(sorted(lines, key=lambda ln: ln.t))
    assert m["stream"] == "stdout" and m["n_lines"] == len(lines) // 2


def test_lines_before_the_first_odometry_do_not_match() -> None:
    early = [OutputLine(24.0, "stdout", "x=0.00 y=0.00 yaw=0.00")]
    m = _measure(early + _lines("x={:.2f} y={:.2f} yaw={:.2f}"))
    assert m["n_correct"] == m["n_lines"] - 1


def test_rate_and_gaps() -> None:
    m = _measure(_lines("{:.2f} {:.2f} {:.2f}", every=30))
    assert m["rate_hz"] == pytest.approx(1.0, abs=0.01) and m["max_gap_s"] == pytest.approx(1.0, abs=0.01)
    assert np.isfinite(m["first_line_s"])
