"""/scan beam for beam against a ray cast computed here, apart from MuJoCo, from the course world's walls and pillars.

The cast is plain 2D geometry (a ray against each box's rectangle by the slab method, against each pillar's circle),
from the scanner's pose, which is the robot's ground-truth pose and the profile's mount. The world's reading minus
the noise it adds (sim.sensors.noise, the profile's stddev) must equal it, beam for beam; the noise itself must be the
profile's Gaussian, change with the seed, and repeat bit for bit.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from sim import GroundTruthSample, Scenario, ScanSample, World
from sim.profile import load_robot
from sim.scenario import Box, Cylinder
from sim.sensors import noise

SECOND = 1_000_000_000


def _ray_box(ox: float, oy: float, dx: float, dy: float, box: Box) -> float:
    """Distance along the ray to the box's rectangle (inf: missed), in the box's own axes."""
    c, s = math.cos(box.yaw), math.sin(box.yaw)
    px, py = (ox - box.x) * c + (oy - box.y) * s, -(ox - box.x) * s + (oy - box.y) * c
    vx, vy = dx * c + dy * s, -dx * s + dy * c
    near, far = -math.inf, math.inf
    for p, v, half in ((px, vx, box.length / 2), (py, vy, box.width / 2)):
        if abs(v) < 1e-15:
            if abs(p) > half:
                return math.inf
            continue
        a, b = sorted(((-half - p) / v, (half - p) / v))
        near, far = max(near, a), min(far, b)
    return near if near <= far and near >= 0 else math.inf


def _ray_circle(ox: float, oy: float, dx: float, dy: float, pillar: Cylinder) -> float:
    fx, fy = ox - pillar.x, oy - pillar.y
    b = fx * dx + fy * dy
    disc = b * b - (fx * fx + fy * fy - pillar.radius ** 2)
    if disc < 0:
        return math.inf
    t = -b - math.sqrt(disc)
    return t if t >= 0 else math.inf


def _cast(scenario: Scenario, pose: tuple[float, float, float], mount: tuple[float, float], angles: np.ndarray,
          range_min: float, range_max: float) -> list[float]:
    x, y, yaw = pose
    ox = x + mount[0] * math.cos(yaw) - mount[1] * math.sin(yaw)
    oy = y + mount[0] * math.sin(yaw) + mount[1] * math.cos(yaw)
    ranges = []
    for angle in angles.tolist():
        dx, dy = math.cos(yaw + angle), math.sin(yaw + angle)
        hits = [_ray_box(ox, oy, dx, dy, o) if isinstance(o, Box) else _ray_circle(ox, oy, dx, dy, o)
                for o in scenario.all_obstacles]
        d = min(hits, default=math.inf)
        ranges.append(d if range_min <= d <= range_max else math.inf)
    return ranges


def _last_scan_and_pose(scenario: Scenario, seconds: float = 1.0) -> tuple[ScanSample, tuple[float, float, float]]:
    world = World(scenario)
    samples = world.advance_to(world.start_ns + round(seconds * SECOND))
    scan = [s for s in samples if isinstance(s, ScanSample)][-1]
    truth = [s for s in samples if isinstance(s, GroundTruthSample) and s.t_ns == scan.t_ns][-1]
    qx, qy, qz, qw = truth.orientation
    return scan, (truth.position[0], truth.position[1], math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz)))


@pytest.mark.parametrize("world,start,robot", [("turtlebot3_world", "default", "turtlebot3_burger"),
                                               ("arena", "south", "turtlebot3_waffle"),
                                               ("corridor", "halfway", "turtlebot3_waffle")])
def test_scan_is_the_independent_cast_plus_the_profiles_noise(world: str, start: str, robot: str) -> None:
    scenario = Scenario(robot=robot, world=world, start=start, seed=7)
    config = load_robot(robot).modes["gazebo"].sensors.scan
    scan, pose = _last_scan_and_pose(scenario)
    angles = config.angle_min + scan.angle_increment * np.arange(config.samples)
    cast = _cast(scenario, pose, config.mount[:2], angles, config.range_min, config.range_max)
    draws = noise(scenario.seed, scan.t_ns, config.samples)
    hits = [i for i, d in enumerate(cast) if math.isfinite(d)]
    assert len(hits) > 30, "the world should be within range of many beams"
    for i, (read, d) in enumerate(zip(scan.ranges, cast)):
        if math.isinf(d):
            assert math.isinf(read), (i, read)
            continue
        expected = min(max(d + config.noise_stddev * draws[i], config.range_min), config.range_max)
        assert read == pytest.approx(expected, abs=1e-6), (i, read, d)


def test_noise_is_the_profiles_gaussian_and_the_seeds() -> None:
    config = load_robot("turtlebot3_waffle").modes["gazebo"].sensors.scan
    assert config.noise_stddev == 0.01  # lds_lfcd_sensor's <noise> in the TurtleBot3 gazebo xacro and SDF
    scans = {seed: _last_scan_and_pose(Scenario(world="arena", start="south", seed=seed))[0] for seed in (1, 2)}
    again = _last_scan_and_pose(Scenario(world="arena", start="south", seed=1))[0]
    assert again.ranges == scans[1].ranges  # bit for bit
    finite = [i for i, r in enumerate(scans[1].ranges) if math.isfinite(r) and math.isfinite(scans[2].ranges[i])]
    differences = np.array([scans[1].ranges[i] - scans[2].ranges[i] for i in finite])
    # the difference of two independent N(0, 0.01²) draws has stddev 0.01·√2
    assert differences.std() == pytest.approx(0.01 * math.sqrt(2), rel=0.25)


def test_a_ros2_run_gets_the_jazzy_simulations_lidar() -> None:
    """Jazzy's model.sdf: the Waffle's gpu_lidar at 10 Hz (Noetic's xacro: 5 Hz), both robots' over 0..6.28 rad."""
    from sim.worlds import open_world

    for robot, rates in (("turtlebot3_waffle", {"ros1": 5, "ros2": 10}), ("turtlebot3_burger", {"ros1": 5, "ros2": 5})):
        for flavour, rate in rates.items():
            world = open_world(Scenario(robot=robot, world="corridor", start="entrance"), flavour)
            world.listen(None)
            scans = [s for s in world.advance_to(world.start_ns + SECOND) if isinstance(s, ScanSample)]
            assert len(scans) == rate and [t.rate_hz for t in world.publications if t.topic == "/scan"] == [rate]
            assert scans[-1].angle_max == (6.28 if flavour == "ros2" else 6.28319)
            assert scans[-1].angle_increment == pytest.approx(scans[-1].angle_max / 359)


def test_the_reused_noise_stream_draws_what_a_fresh_philox_draws() -> None:
    """The scanner's one generator, its state set per sweep, gives the draws of Philox(key=seed, counter=t_ns)."""
    from sim.sensors import NoiseStream

    stream = NoiseStream(-3)
    for t_ns in (5, 200_000_000, 91_400_000_000, 200_000_000):
        fresh = np.random.Generator(np.random.Philox(key=-3 & (2 ** 64 - 1), counter=t_ns)).standard_normal(360)
        assert (stream.draws(t_ns, 360) == fresh).all()
