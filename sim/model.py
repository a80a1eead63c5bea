"""MuJoCo model of a diff-drive robot profile, built to the reference recipe that tracks commanded twists to ~0.01 %.

Each distinct model is compiled (and settled) once per process and cached by its MJCF text, which holds everything
that shapes it; every world gets its own copy of the compiled model, so a run that changed its model could not
leak into the next one.

Recipe (robots-and-sim.md §2–§4): free-joint base; sphere wheels (one contact each, no scrub torque) with priority 1
so their stiff solref is not averaged with the floor's; frictionless priority-1 ball casters (condim 1); implicitfast,
elliptic cone, impratio 10; ``<velocity>`` servos plus joint armature; contact margin equal to the static
penetration so the rolling radius is the geometric one.
"""
from __future__ import annotations

import copy
import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import mujoco

from sim.clock import PHYSICS_HZ
from sim.profile import RobotProfile
from sim.scenario import Box, Cylinder

CONTACT_SOLREF = "0.004 1"
CONTACT_SOLIMP = "0.95 0.99 0.001"
WHEEL_FRICTION = "1 0.005 0.0001"
SETTLE_STEPS = PHYSICS_HZ // 2  # long enough for the contacts to reach static penetration
CACHED_MODELS = 64  # distinct compiled models kept per process (a robot with a few obstacle layouts each)
# Geom groups: obstacles 0 (what a laser sees), the robot 1, the floor 2.
OBSTACLE_GROUP, ROBOT_GROUP, FLOOR_GROUP = 0, 1, 2
# Contact bits: the body box (bit 2) meets obstacles only, never the floor or the wheels (bit 1), which meet both.
BODY_BITS, OBSTACLE_BITS = 2, 3


@dataclass(frozen=True)
class RobotModel:
    """A compiled model plus the addresses the world reads every tick."""

    model: mujoco.MjModel
    wheel_radius: float  # the physical (actual) rolling radius, which imperfections may change
    wheel_qpos: tuple[int, int]  # left, right
    wheel_qvel: tuple[int, int]
    wheel_ctrl: tuple[int, int]
    base_body: int
    obstacle_geoms: tuple[int, ...]
    floor_geom: int


def _obstacle(index: int, obstacle: Box | Cylinder) -> str:
    """The MJCF geom of one fixed obstacle, standing on the floor."""
    if isinstance(obstacle, Cylinder):
        shape = f'type="cylinder" size="{obstacle.radius!r} {obstacle.height / 2!r}"'
    else:
        half = obstacle.yaw / 2
        shape = (f'type="box" size="{obstacle.length / 2!r} {obstacle.width / 2!r} {obstacle.height / 2!r}" '
                 f'quat="{math.cos(half)!r} 0 0 {math.sin(half)!r}"')
    return f"""
    <geom name="obstacle_{index}" group="{OBSTACLE_GROUP}" contype="{OBSTACLE_BITS}" conaffinity="{OBSTACLE_BITS}" {shape} pos="{obstacle.x!r} {obstacle.y!r} {obstacle.height / 2!r}"/>"""


def mjcf(profile: RobotProfile, wheel_radius: float, obstacles: Sequence[Box | Cylinder] = ()) -> str:
    """The MJCF text of ``profile`` with wheels of physical radius ``wheel_radius`` and the fixed ``obstacles``.

    Floats are written exactly (repr), so the same inputs always compile to the same model.
    """
    g, a = profile.geometry, profile.actuator
    half = g.wheel_separation / 2
    wheels = "".join(
        f"""
      <body name="wheel_{side}" pos="0 {y!r} {wheel_radius!r}">
        <joint name="wheel_{side}" type="hinge" axis="0 1 0" armature="{a.armature!r}"/>
        <geom name="wheel_{side}" class="contact" type="sphere" size="{wheel_radius!r}" mass="{g.wheel_mass!r}"
              friction="{WHEEL_FRICTION}" condim="3"/>
      </body>"""
        for side, y in (("left", half), ("right", -half))
    )
    casters = "".join(
        f"""
      <geom name="caster_{i}" class="contact" type="sphere" size="{c.radius!r}"
            pos="{c.x!r} {c.y!r} {c.radius + c.clearance!r}" friction="0" condim="1"/>"""
        for i, c in enumerate(g.casters)
    )
    actuators = "".join(
        f"""
    <velocity name="wheel_{side}" joint="wheel_{side}" kv="{a.kv!r}" forcerange="{-a.forcerange!r} {a.forcerange!r}"/>"""
        for side in ("left", "right")
    )
    body = ""
    if obstacles and g.body is not None:  # on an open floor nothing could touch it: the model stays as it was
        b = g.body
        body = f"""
      <geom name="body" group="{ROBOT_GROUP}" type="box" size="{b.length / 2!r} {b.width / 2!r} {b.height / 2!r}"
            pos="{b.x!r} 0 {b.z!r}" contype="{BODY_BITS}" conaffinity="{BODY_BITS}"/>"""
    com = " ".join(repr(v) for v in g.com)
    inertia = " ".join(repr(v) for v in g.base_inertia)
    return f"""<mujoco model="{profile.name}">
  <compiler angle="radian" autolimits="true"/>
  <option timestep="{1 / PHYSICS_HZ!r}" integrator="implicitfast" cone="elliptic" impratio="10"/>
  <default>
    <default class="contact">
      <geom group="{ROBOT_GROUP}" priority="1" solref="{CONTACT_SOLREF}" solimp="{CONTACT_SOLIMP}"/>
    </default>
  </default>
  <worldbody>
    <geom name="floor" group="{FLOOR_GROUP}" type="plane" size="0 0 1"/>{"".join(_obstacle(i, o) for i, o in enumerate(obstacles))}
    <body name="base">
      <freejoint name="base"/>
      <inertial pos="{com}" mass="{g.base_mass!r}" diaginertia="{inertia}"/>{body}{casters}{wheels}
    </body>
  </worldbody>
  <actuator>{actuators}
  </actuator>
</mujoco>
"""


def build_model(profile: RobotProfile, wheel_radius_scale: float = 1.0,
                obstacles: Sequence[Box | Cylinder] = ()) -> RobotModel:
    """Compile ``profile`` (wheels scaled by ``wheel_radius_scale``) among ``obstacles``, and set each robot contact's
    margin to its static penetration; the caller owns the returned model (a copy of the process's cached one)."""
    wheel_radius = profile.geometry.wheel_radius * wheel_radius_scale
    compiled = _compile(mjcf(profile, wheel_radius, obstacles), wheel_radius, len(obstacles))
    return replace(compiled, model=copy.copy(compiled.model))


@functools.lru_cache(maxsize=CACHED_MODELS)
def _compile(xml: str, wheel_radius: float, obstacle_count: int) -> RobotModel:
    """The compiled, settled model of ``xml``; cached, so it must never be handed out (``build_model`` copies it)."""
    model = mujoco.MjModel.from_xml_string(xml)
    obstacle_geoms = tuple(mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, f"obstacle_{i}")
                           for i in range(obstacle_count))
    _compensate_penetration(model, obstacle_geoms)
    joints = [mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, f"wheel_{side}") for side in ("left", "right")]
    actuators = [mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_ACTUATOR, f"wheel_{side}") for side in ("left", "right")]
    return RobotModel(
        model=model,
        wheel_radius=wheel_radius,
        wheel_qpos=(int(model.jnt_qposadr[joints[0]]), int(model.jnt_qposadr[joints[1]])),
        wheel_qvel=(int(model.jnt_dofadr[joints[0]]), int(model.jnt_dofadr[joints[1]])),
        wheel_ctrl=(actuators[0], actuators[1]),
        base_body=mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "base"),
        obstacle_geoms=obstacle_geoms,
        floor_geom=mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "floor"),
    )


def _compensate_penetration(model: mujoco.MjModel, obstacle_geoms: tuple[int, ...]) -> None:
    """Let the robot settle, then give each touching geom a margin equal to its penetration (so it rests at distance 0).

    Friction acts at the middle of the penetration, so a sinking wheel rolls on r − pen/2; with the margin the
    constraint's equilibrium moves to the surface and the rolling radius is the geometric one.
    """
    # The robot settles at the origin, where an obstacle may stand: obstacles do not collide meanwhile.
    saved = [(int(model.geom_contype[g]), int(model.geom_conaffinity[g])) for g in obstacle_geoms]
    model.geom_contype[list(obstacle_geoms)] = 0
    model.geom_conaffinity[list(obstacle_geoms)] = 0
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=SETTLE_STEPS)
    for geom, (contype, conaffinity) in zip(obstacle_geoms, saved):
        model.geom_contype[geom], model.geom_conaffinity[geom] = contype, conaffinity
    floor = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "floor")
    for contact in data.contact[: data.ncon]:
        robot_geom = contact.geom2 if contact.geom1 == floor else contact.geom1
        model.geom_margin[robot_geom] = max(float(model.geom_margin[robot_geom]), -float(contact.dist))
