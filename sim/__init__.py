"""rosgrade's simulated worlds: robot profiles, MuJoCo physics, base drivers, odometry, the clock, and turtlesim."""
from __future__ import annotations

from sim.profile import ProfileError, RobotProfile, available_robots, load_robot
from sim.samples import (ColorSample, CommandSample, GroundTruthSample, ImuSample, JointStateSample, LogSample,
                         OdometrySample, Sample, ScanSample, ServiceResult, TransformSample, TurtlePoseSample,
                         WorldService, WorldTopic)
from sim.scenario import Imperfections, Pose2D, Scenario, ScriptedCommand
from sim.turtlesim import TurtlesimError, TurtlesimWorld
from sim.turtlesim_windows import TurtlesimWindows
from sim.world import SimError, World
from sim.worlds import WORLD_NODE_NAMES, AnyWorld, open_world

__all__ = [
    "ColorSample",
    "LogSample",
    "TurtlePoseSample",
    "TurtlesimError",
    "TurtlesimWorld",
    "TurtlesimWindows",
    "AnyWorld",
    "open_world",
    "WORLD_NODE_NAMES",
    "CommandSample",
    "GroundTruthSample",
    "ImuSample",
    "JointStateSample",
    "Imperfections",
    "OdometrySample",
    "Pose2D",
    "ProfileError",
    "RobotProfile",
    "Sample",
    "ScanSample",
    "ServiceResult",
    "Scenario",
    "ScriptedCommand",
    "SimError",
    "TransformSample",
    "World",
    "WorldService",
    "WorldTopic",
    "available_robots",
    "load_robot",
]
