"""LiDAR readings a node printed, checked against what its /scan read (COM2009 Part 3 Ex 4: the distance and the
direction of the nearest object ahead).

Each printed or logged line holding a distance (m) and an angle (degrees) is one reading. The scans the node can have
had then are rebuilt from the world's geometry at the robot's ground-truth pose at each sweep (the LiDAR's beams from
its mount, nearest wall or pillar; the simulated noise, 1 cm, is well inside the tolerance): a reading is right when
it matches the nearest object within ``arc_deg`` of straight ahead in one of the ``lag_scans`` sweeps before it.
"""
from __future__ import annotations

import math
import re

from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.run import OutputLine, RunData
from grader.metrics.stop_distance import ray_distance
from sim.profile import ProfileError, ScanConfig, load_robot

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_WITH_METRES = re.compile(rf"({_NUMBER})\s*(?:m\b|metres\b|meters\b)")
_WITH_DEGREES = re.compile(rf"({_NUMBER})\s*(?:°|deg\b|degs\b|degrees\b)")
_WITH_RADIANS = re.compile(rf"({_NUMBER})\s*(?:rad\b|rads\b|radians\b)")
_ANY = re.compile(_NUMBER)
# What rclpy logs when a subscription cannot match a publisher's QoS (tests/conformance_ros2/qos_matrix_jazzy.json).
_INCOMPATIBLE = re.compile(r"New publisher discovered on topic '(?P<topic>[^']*)', offering incompatible QoS\..*"
                           r"Last incompatible policy: (?P<policy>\w+)")


class Params(TrajectoryParams):
    """The arc the task calls "ahead", the tolerances, and how many sweeps back a reading may be from."""

    arc_deg: float = Field(20.0, gt=0, le=180)  # either side of straight ahead
    distance_tolerance: float = Field(0.05, gt=0)  # metres
    angle_tolerance_deg: float = Field(5.0, gt=0)
    lag_scans: int = Field(3, ge=1)
    noise_margin: float = Field(0.03, ge=0)  # metres: beams this close to the nearest count as nearest (3σ noise)


def reading(text: str) -> tuple[float, float] | None:
    """(distance m, angle deg) from a line: numbers marked m and deg, ° or rad if it has them, else its first two."""
    metres, degrees, radians = _WITH_METRES.search(text), _WITH_DEGREES.search(text), _WITH_RADIANS.search(text)
    if metres and degrees:
        return float(metres.group(1)), float(degrees.group(1))
    if metres and radians:
        return float(metres.group(1)), math.degrees(float(radians.group(1)))
    numbers = _ANY.findall(text)
    if len(numbers) >= 2 and not (metres or degrees or radians):
        return float(numbers[0]), float(numbers[1])
    return None


def beams_ahead(run: RunData, scan: ScanConfig, pose: tuple[float, float, float], arc: float
                ) -> list[tuple[float, float]]:
    """(angle in degrees, noise-free range) of each beam within ``arc`` rad of ahead at ``pose`` (inf: nothing in
    range)."""
    x, y, yaw = pose
    mx = x + scan.mount[0] * math.cos(yaw) - scan.mount[1] * math.sin(yaw)
    my = y + scan.mount[0] * math.sin(yaw) + scan.mount[1] * math.cos(yaw)
    increment = (scan.angle_max - scan.angle_min) / (scan.samples - 1)
    beams = []
    for i in range(scan.samples):
        angle = math.remainder(scan.angle_min + i * increment, 2 * math.pi)
        if abs(angle) > arc:
            continue
        dx, dy = math.cos(yaw + angle), math.sin(yaw + angle)
        d = min((ray_distance(mx, my, dx, dy, o) for o in run.obstacles), default=math.inf)
        beams.append((math.degrees(angle), d if scan.range_min <= d <= scan.range_max else math.inf))
    return beams


def nearest(beams: list[tuple[float, float]]) -> tuple[float, float]:
    """(distance, angle in degrees) of the beam that reads least (inf, nan: none in range)."""
    found = [(d, a) for a, d in beams if math.isfinite(d)]
    return min(found) if found else (math.inf, math.nan)


def _matches(read: tuple[float, float], beams: list[tuple[float, float]], params: Params) -> tuple[bool, bool]:
    """Whether the distance is the nearest beam's, and whether the angle is that of a beam reading as near (beams
    within the noise of the nearest are equally "the nearest" in a noisy scan)."""
    distance, angle = read
    least = nearest(beams)[0]
    if not math.isfinite(least) or abs(distance - least) > params.distance_tolerance:
        return False, False
    near = [a for a, d in beams if d <= least + params.noise_margin]
    return True, any(abs(math.degrees(math.remainder(math.radians(angle - a), 2 * math.pi)))
                     <= params.angle_tolerance_deg for a in near)


def _readings(lines: tuple[OutputLine, ...]) -> list[tuple[float, float, float]]:
    """(t, distance, angle) of the stream that holds most readings (loginfo shows on stdout and /rosout alike;
    /rosout wins a tie)."""
    by_stream: dict[str, list[tuple[float, float, float]]] = {}
    for line in lines:
        found = reading(line.message()[1])
        if found is not None:
            by_stream.setdefault(line.stream, []).append((line.t, *found))
    rank = {"rosout": 0, "stdout": 1}
    return max(by_stream.items(), key=lambda kv: (len(kv[1]), -rank.get(kv[0], 2)), default=("", []))[1]


def incompatible_qos(lines: tuple[OutputLine, ...], topic: str = "/scan") -> str:
    """The policy rclpy named when the node's subscription to ``topic`` could not match the publisher ("": none)."""
    for line in lines:
        found = _INCOMPATIBLE.search(line.text)
        if found and found.group("topic") == topic:
            return found.group("policy")
    return ""


def measure(run: RunData, params: Params) -> Measurement:
    """Each reading against the nearest object ahead in the sweeps just before it; the readings' rate."""
    try:
        profile = load_robot(run.robot)
    except ProfileError:
        raise MetricError("the recording does not say which robot ran, so its LiDAR is unknown") from None
    scan = profile.modes[profile.default_mode].sensors.scan
    if scan is not None:  # as the simulation of the node's ROS version publishes it (Jazzy's Waffle: 10 Hz)
        scan = scan.for_flavour("ros2" if run.client_library == "rclpy" else "ros1")
    if scan is None:
        raise MetricError("this robot has no LiDAR to check readings against")
    traj = run.trajectory(params.source)
    if len(traj) == 0:
        raise MetricError("the recording has no poses to locate the robot")
    readings = [r for r in _readings(run.lines) if r[0] >= run.start_time]
    period = 1.0 / scan.rate_hz
    sweeps: dict[int, list[tuple[float, float]]] = {}
    right = right_angles = 0
    first_wrong = ""
    for t, distance, angle in readings:
        sweep = math.floor(t / period + 1e-9)
        matched = (False, False)
        for k in range(sweep, sweep - params.lag_scans, -1):
            if k not in sweeps:
                at = min(int(traj.t.searchsorted(k * period)), len(traj) - 1)
                pose = float(traj.x[at]), float(traj.y[at]), float(traj.yaw[at])
                sweeps[k] = beams_ahead(run, scan, pose, math.radians(params.arc_deg))
            found = _matches((distance, angle), sweeps[k], params)
            matched = max(matched, found)
            if matched == (True, True):
                break
        right += matched[0]
        right_angles += matched[1]
        if not matched[0] and not first_wrong:
            truth = nearest(sweeps[sweep])
            first_wrong = (f"at {t - run.start_time:.1f} s the node printed {distance:g} m at {angle:g}°; /scan read "
                           f"{truth[0]:.2f} m at {truth[1]:.0f}°")
    mismatch = incompatible_qos(run.lines)
    times = [r[0] for r in readings]
    span = times[-1] - times[0] if len(times) > 1 else 0.0
    n = len(readings)
    return {
        "n_readings": n,
        "distance_fraction": right / n if n else 0.0,
        "angle_fraction": right_angles / n if n else 0.0,
        "first_wrong": first_wrong,
        "rate_hz": (n - 1) / span if span > 0 else 0.0,
        "max_gap_s": max((b - a for a, b in zip(times, times[1:])), default=math.inf),
        "incompatible_qos": mismatch,
        "qos_mismatch": bool(mismatch),
    }


METRIC = Metric(
    name="lidar_distance",
    params=Params,
    quantities=frozenset({"n_readings", "distance_fraction", "angle_fraction", "first_wrong", "rate_hz",
                          "max_gap_s", "incompatible_qos", "qos_mismatch"}),
    measure=measure,
)
