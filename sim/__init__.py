"""rosgrade's simulated world: robot profiles, MuJoCo physics, base drivers, odometry and the clock."""
from __future__ import annotations

from sim.profile import ProfileError, RobotProfile, available_robots, load_robot
from sim.samples import CommandSample, GroundTruthSample, OdometrySample, Sample, TransformSample
from sim.scenario import Imperfections, Pose2D, Scenario, ScriptedCommand
from sim.world import SimError, World

__all__ = [
    "CommandSample",
    "GroundTruthSample",
    "Imperfections",
    "OdometrySample",
    "Pose2D",
    "ProfileError",
    "RobotProfile",
    "Sample",
    "Scenario",
    "ScriptedCommand",
    "SimError",
    "TransformSample",
    "World",
    "available_robots",
    "load_robot",
]
