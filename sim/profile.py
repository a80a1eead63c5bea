"""Robot profiles: one TOML per robot in ``sim/robots/``, validated on load so that a bad file fails with its field named."""
from __future__ import annotations

import functools
import tomllib
from pathlib import Path
from typing import Annotated, Literal, Union

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from sim.clock import PHYSICS_HZ

ROBOTS_DIR = Path(__file__).parent / "robots"

PositiveFloat = Annotated[float, Field(gt=0, allow_inf_nan=False)]
Vec3 = tuple[float, float, float]
Diagonal6 = tuple[float, float, float, float, float, float]


class ProfileError(Exception):
    """A robot profile that is missing, unreadable or invalid (the message names the file and the field)."""


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class Caster(_Model):
    """A frictionless ball caster fixed to the base; ``clearance`` lifts it off the floor (it only touches when pitching)."""

    x: float
    y: float
    radius: PositiveFloat
    clearance: float = Field(0.0, ge=0)


class Body(_Model):
    """The base's collision box (URDF base_link collision), centred ``x`` ahead of and ``z`` above the base frame: what
    touches a wall or pillar besides the wheels. Built only among obstacles, so an open floor's physics is unchanged."""

    x: float
    z: PositiveFloat
    length: PositiveFloat
    width: PositiveFloat
    height: PositiveFloat

    @property
    def front(self) -> float:
        """How far ahead of the base frame the body ends (the robot's front)."""
        return self.x + self.length / 2


class Geometry(_Model):
    """Nominal drive geometry and mass properties (base frame: origin on the floor midway between the wheels, x forward)."""

    wheel_radius: PositiveFloat
    wheel_separation: PositiveFloat
    wheel_mass: PositiveFloat
    base_mass: PositiveFloat
    com: Vec3
    base_inertia: tuple[PositiveFloat, PositiveFloat, PositiveFloat]
    casters: list[Caster] = Field(min_length=1)
    body: Body | None = None


class Actuator(_Model):
    """Wheel velocity servo: MuJoCo ``<velocity kv forcerange>`` plus the joint's reflected rotor inertia (armature)."""

    kv: PositiveFloat
    forcerange: PositiveFloat
    armature: float = Field(ge=0, allow_inf_nan=False)


class Limits(_Model):
    """Advertised maximum speeds (what teleop and task authors use; the base driver may clamp differently)."""

    max_linear: PositiveFloat
    max_angular: PositiveFloat


class GazeboDiffDriveConfig(_Model):
    """``gazebo_ros_diff_drive`` (ROS 1): wheel rim speeds ramp at ``wheel_acceleration``; no clamp."""

    kind: Literal["gazebo_diff_drive"]
    wheel_acceleration: PositiveFloat


class OpenCrConfig(_Model):
    """TurtleBot3 OpenCR ROS 1 firmware: twist clamp, per-wheel Dynamixel clamp and truncation to velocity units."""

    kind: Literal["opencr"]
    max_linear: PositiveFloat
    max_angular: PositiveFloat
    wheel_limit_units: int = Field(gt=0)
    rpm_per_unit: PositiveFloat


class DiffDriveControllerConfig(_Model):
    """ros_controllers ``diff_drive_controller``: linear and angular speed/acceleration limited independently."""

    kind: Literal["diff_drive_controller"]
    max_linear: PositiveFloat
    max_linear_acceleration: PositiveFloat
    max_angular: PositiveFloat
    max_angular_acceleration: PositiveFloat


class DirectConfig(_Model):
    """A base that sets wheel speeds straight from the command (Kobuki)."""

    kind: Literal["direct"]


DriverConfig = Annotated[
    Union[GazeboDiffDriveConfig, OpenCrConfig, DiffDriveControllerConfig, DirectConfig], Field(discriminator="kind")
]


class OdometryConfig(_Model):
    """What the base publishes as odometry: topic, rate, frames, and whether it is the world pose or dead reckoning."""

    topic: str
    rate_hz: int = Field(gt=0)
    frame_id: str
    child_frame_id: str
    source: Literal["world", "wheels"]
    pose_covariance: Diagonal6
    twist_covariance: Diagonal6


class TfConfig(_Model):
    """The odom → base transform the robot stack broadcasts on /tf."""

    rate_hz: int = Field(gt=0)
    parent: str
    child: str


class ImuConfig(_Model):
    """An IMU on the base: orientation, body angular velocity and proper acceleration (gravity included)."""

    topic: str
    rate_hz: int = Field(gt=0)
    frame_id: str


class JointConfig(_Model):
    """One wheel joint as the robot names it, and which side's wheel it turns with."""

    name: str
    wheel: Literal["left", "right"]


class JointStatesConfig(_Model):
    """sensor_msgs/JointState of the wheel joints: positions always, velocities when the publisher fills them."""

    topic: str
    rate_hz: int = Field(gt=0)
    frame_id: str = ""
    joints: list[JointConfig] = Field(min_length=1)
    velocities: bool = False


class ScanVersion(_Model):
    """What a ROS version's simulation publishes differently from the profile's scanner (unset: the same)."""

    rate_hz: int | None = Field(None, gt=0)
    angle_max: float | None = None
    reliability: Literal["RELIABLE", "BEST_EFFORT"] | None = None


class ScanConfig(_Model):
    """A planar laser scanner: ``samples`` beams from ``angle_min`` to ``angle_max`` (inclusive) about the frame's z.

    ``mount`` is the scanner's position in the base frame. Beams that hit nothing between ``range_min`` and
    ``range_max`` read +inf, as Gazebo's ray sensor reports them. ``noise_stddev``: Gaussian noise (mean 0) on each
    beam that hits, the reading then clamped to [range_min, range_max], as Gazebo applies its ``<noise>``.
    """

    topic: str
    rate_hz: int = Field(gt=0)
    frame_id: str
    mount: Vec3
    samples: int = Field(ge=2)
    angle_min: float
    angle_max: float
    range_min: float = Field(ge=0)
    range_max: PositiveFloat
    noise_stddev: float = Field(0.0, ge=0)
    # ROS 2: the reliability /scan is offered with (VOLATILE either way); a RELIABLE subscriber misses BEST_EFFORT
    reliability: Literal["RELIABLE", "BEST_EFFORT"] = "RELIABLE"
    ros2: ScanVersion | None = None  # the ROS 2 (Jazzy) simulation's differences

    def for_flavour(self, flavour: str) -> ScanConfig:
        """The scanner as the simulation of a ROS version ("ros1", "ros2") publishes it."""
        if flavour != "ros2" or self.ros2 is None:
            return self
        return self.model_copy(update={k: v for k, v in self.ros2.model_dump().items() if v is not None})

    @model_validator(mode="after")
    def _check(self) -> ScanConfig:
        if self.angle_max <= self.angle_min or self.range_max <= self.range_min:
            raise ValueError("expected angle_min < angle_max and range_min < range_max")
        return self


class Sensors(_Model):
    """The robot's sensor topics besides odometry (each optional)."""

    imu: ImuConfig | None = None
    joint_states: JointStatesConfig | None = None
    scan: ScanConfig | None = None


class BaseMode(_Model):
    """One way the robot's base can behave (simulated plugin, real firmware, ...): everything that differs between them."""

    description: str
    command_topics: list[str] = Field(min_length=1)
    command_timeout: PositiveFloat | None = None  # seconds; None: the last command is held forever
    control_rate_hz: int = Field(gt=0)
    driver: DriverConfig
    odometry: OdometryConfig
    tf: TfConfig | None = None
    sensors: Sensors = Sensors()


class RobotProfile(_Model):
    """A validated robot profile: geometry, servo, advertised limits and its base modes."""

    name: str
    description: str
    default_mode: str
    geometry: Geometry
    actuator: Actuator
    limits: Limits
    modes: dict[str, BaseMode] = Field(min_length=1)

    @model_validator(mode="after")
    def _check(self) -> RobotProfile:
        if self.default_mode not in self.modes:
            raise ValueError(f"default_mode {self.default_mode!r} is not one of the modes {sorted(self.modes)}")
        for mode_name, mode in self.modes.items():
            rates = {"control_rate_hz": mode.control_rate_hz, "odometry.rate_hz": mode.odometry.rate_hz}
            if mode.tf is not None:
                rates["tf.rate_hz"] = mode.tf.rate_hz
            for sensor in ("imu", "joint_states", "scan"):
                config = getattr(mode.sensors, sensor)
                if config is not None:
                    rates[f"sensors.{sensor}.rate_hz"] = config.rate_hz
            scan = mode.sensors.scan
            if scan is not None and scan.ros2 is not None and scan.ros2.rate_hz is not None:
                rates["sensors.scan.ros2.rate_hz"] = scan.ros2.rate_hz
            for field, rate in rates.items():
                if PHYSICS_HZ % rate:
                    raise ValueError(
                        f"modes.{mode_name}.{field} = {rate}: expected a rate that divides the {PHYSICS_HZ} Hz physics step"
                    )
        return self

    @classmethod
    def from_toml(cls, path: str | Path) -> RobotProfile:
        """Read and validate one profile file; any problem raises ``ProfileError`` naming the file and the field."""
        path = Path(path)
        try:
            raw = tomllib.loads(path.read_text(encoding="utf-8"))
        except OSError as exc:
            raise ProfileError(f"{path}: cannot read robot profile ({exc.strerror})") from None
        except tomllib.TOMLDecodeError as exc:
            raise ProfileError(f"{path}: not valid TOML ({exc})") from None
        try:
            profile = cls.model_validate(raw)
        except ValidationError as exc:
            raise ProfileError(f"{path}: invalid robot profile\n{_describe(exc)}") from None
        if profile.name != path.stem:
            raise ProfileError(f"{path}: field 'name' is {profile.name!r}; expected the file name {path.stem!r}")
        return profile


def _describe(exc: ValidationError) -> str:
    """One line per problem: the dotted field, what was expected, and what was found."""
    lines = []
    for err in exc.errors(include_url=False):
        field = ".".join(str(part) for part in err["loc"]) or "(top level)"
        found = "" if err["type"] == "missing" else f" (got {err['input']!r})"
        lines.append(f"  field '{field}': {err['msg']}{found}")
    return "\n".join(lines)


def available_robots() -> list[str]:
    """Names of the bundled robot profiles."""
    return sorted(path.stem for path in ROBOTS_DIR.glob("*.toml"))


@functools.lru_cache(maxsize=None)
def load_robot(name: str) -> RobotProfile:
    """The bundled profile ``name`` (e.g. "turtlebot3_waffle"), validated; profiles are immutable, so it is cached."""
    path = ROBOTS_DIR / f"{name}.toml"
    if not path.is_file():
        raise ProfileError(f"{path}: unknown robot {name!r}; available: {', '.join(available_robots())}")
    return RobotProfile.from_toml(path)


def covariance_matrix(diagonal: Diagonal6) -> tuple[float, ...]:
    """The 36-value row-major covariance with ``diagonal`` on its diagonal (ROS message layout)."""
    return tuple(diagonal[i // 6] if i % 7 == 0 else 0.0 for i in range(36))


__all__ = [
    "BaseMode",
    "ProfileError",
    "RobotProfile",
    "available_robots",
    "covariance_matrix",
    "load_robot",
]
