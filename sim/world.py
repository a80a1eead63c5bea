"""The world: one robot in MuJoCo, its base driver and odometry, advanced in exact integer-nanosecond sim time.

Physics steps at 600 Hz (``sim.clock``). Between ticks it is stepped in one ``mj_step(nstep=n)`` batch; Python runs
only on ticks: the control tick (latch the command, run the base driver, set the servo targets), the odometry and /tf
ticks and the 50 Hz ground truth. Same scenario → same bits, on one machine and MuJoCo version.
"""
from __future__ import annotations

import math
from collections.abc import Collection, Mapping

import mujoco

from sim.base_driver import make_driver
from sim.clock import last_step_at, step_ns, steps_per_tick
from sim.model import build_model
from sim.odometry import Estimate, WheelOdometry, WorldPoseOdometry, ground_truth, quaternion_yaw
from sim.profile import RobotProfile, covariance_matrix, load_robot
from sim.samples import (CommandSample, GroundTruthSample, OdometrySample, Sample, ServiceResult, TransformSample,
                         WorldService, WorldTopic)
from sim.scenario import Scenario, ScenarioTimes
from sim.sensors import Imu, JointStates, Scanner

GROUND_TRUTH_HZ = 50  # above every odometry rate (30, 50 Hz); each sample is a recorded message
GROUND_TRUTH_TOPIC = "/ground_truth/odom"
GROUND_TRUTH_FRAME = "world"
TF_TOPIC = "/tf"


NODE_NAME = "/gazebo"  # Gazebo's node publishes the simulated robot's topics

class SimError(Exception):
    """A world that cannot be built as asked, or a call that breaks the world's contract (e.g. going back in time)."""


class World(ScenarioTimes):
    """One run of a robot: ``command`` it, ``advance_to`` a time, collect the samples it published on the way."""

    def __init__(self, scenario: Scenario, profile: RobotProfile | None = None) -> None:
        self.scenario = scenario
        self.profile = profile if profile is not None else load_robot(scenario.robot)
        self.mode_name = scenario.base_mode or self.profile.default_mode
        if self.mode_name not in self.profile.modes:
            raise SimError(f"robot {self.profile.name} has no base mode {self.mode_name!r}; expected one of {sorted(self.profile.modes)}")
        self.mode = self.profile.modes[self.mode_name]
        self._topics = tuple(self.mode.command_topics)
        for i, command in enumerate(scenario.script):
            if command.topic is not None and command.topic not in self._topics:
                raise SimError(f"script[{i}].topic {command.topic!r} is not a command topic of {self.profile.name}; expected one of {self._topics}")

        geometry = self.profile.geometry
        robot = build_model(self.profile, scenario.imperfections.wheel_radius_scale, scenario.obstacles)
        self.model = robot.model
        self.data = mujoco.MjData(self.model)
        pose = scenario.initial_pose
        self.data.qpos[:7] = (pose.x, pose.y, 0.0, math.cos(pose.yaw / 2), 0.0, 0.0, math.sin(pose.yaw / 2))
        self._wheel_qvel = robot.wheel_qvel
        self._wheel_ctrl = robot.wheel_ctrl

        self._latch, self._driver = make_driver(self.mode, geometry)
        self._odometry: WheelOdometry | WorldPoseOdometry = (
            WorldPoseOdometry()
            if self.mode.odometry.source == "world"
            else WheelOdometry(geometry.wheel_radius, geometry.wheel_separation, robot.wheel_qpos, 0, self.data)
        )
        self._pose_covariance = covariance_matrix(self.mode.odometry.pose_covariance)
        self._twist_covariance = covariance_matrix(self.mode.odometry.twist_covariance)
        self._control_every = steps_per_tick(self.mode.control_rate_hz)
        self._odometry_every = steps_per_tick(self.mode.odometry.rate_hz)
        self._tf_every = steps_per_tick(self.mode.tf.rate_hz) if self.mode.tf is not None else None
        self._truth_every = steps_per_tick(GROUND_TRUTH_HZ)
        sensors = self.mode.sensors
        self._sensors: list[tuple[int, Imu | JointStates | Scanner]] = []
        if sensors.imu is not None:
            self._sensors.append((steps_per_tick(sensors.imu.rate_hz), Imu(sensors.imu, self.model, 0, self.data)))
        if sensors.joint_states is not None:
            self._sensors.append((steps_per_tick(sensors.joint_states.rate_hz), JointStates(sensors.joint_states, robot)))
        if sensors.scan is not None:
            self._sensors.append((steps_per_tick(sensors.scan.rate_hz), Scanner(sensors.scan, robot)))
        self._output_periods = tuple(
            p for p in (self._odometry_every, self._tf_every, self._truth_every, *(p for p, _ in self._sensors))
            if p is not None
        )
        self._topic_periods = {topic.topic: steps_per_tick(topic.rate_hz) for topic in self.publications}
        # The ticks repeat every `cycle` steps: precompute, for each step in the cycle, the distance to the next tick.
        self._cycle = math.lcm(self._control_every, *self._output_periods)
        ticks = [r for r in range(self._cycle) if any(r % p == 0 for p in (self._control_every, *self._output_periods))]
        self._to_next_tick = [next((t for t in ticks if t > r), self._cycle) - r for r in range(self._cycle)]

        start_ns = scenario.start_ns
        self._script = [(start_ns + command.t_ns, command) for command in scenario.script]
        self._next_script = 0
        self._command = (0.0, 0.0)
        self._wheel_targets = (0.0, 0.0)
        self._k = 0
        self._time_ns = 0
        self._estimate: Estimate  # set by the odometry tick at step 0
        self._tick(0, None)
        # The world has been running since 0; commands scripted for the start itself come out of the first advance_to.
        self._pending: list[Sample] = []
        self._run(start_ns, self._pending, emit=False)

    # -- the contract (DEVELOPERS.md) ------------------------------------------------------------------------------

    @property
    def publications(self) -> tuple[WorldTopic, ...]:
        """Every topic this world publishes, with its type and rate (the session routes samples by these)."""
        mode, sensors = self.mode, self.mode.sensors
        declared = [WorldTopic(mode.odometry.topic, "nav_msgs/Odometry", mode.odometry.rate_hz)]
        if mode.tf is not None:
            declared.append(WorldTopic(TF_TOPIC, "tf2_msgs/TFMessage", mode.tf.rate_hz, shared=True))
        declared.append(WorldTopic(GROUND_TRUTH_TOPIC, "nav_msgs/Odometry", GROUND_TRUTH_HZ, to_nodes=False))
        if sensors.imu is not None:
            declared.append(WorldTopic(sensors.imu.topic, "sensor_msgs/Imu", sensors.imu.rate_hz))
        if sensors.joint_states is not None:
            declared.append(WorldTopic(sensors.joint_states.topic, "sensor_msgs/JointState",
                                        sensors.joint_states.rate_hz))
        if sensors.scan is not None:
            declared.append(WorldTopic(sensors.scan.topic, "sensor_msgs/LaserScan", sensors.scan.rate_hz))
        return tuple(declared)

    @property
    def odometry_topic(self) -> str:
        """Where the robot publishes its odometry (what graders read the robot's own belief from)."""
        return self.mode.odometry.topic

    @property
    def command_topics(self) -> tuple[str, ...]:
        """Topics the robot's base listens on (the first is where scripted commands go by default)."""
        return self._topics

    @property
    def node_name(self) -> str:
        """The ROS node that publishes this world's topics (the callerid recordings name)."""
        return NODE_NAME

    @property
    def sim_clock(self) -> bool:
        """Gazebo publishes /clock and its launch files set /use_sim_time: nodes run on the simulated clock."""
        return True

    @property
    def services(self) -> tuple[WorldService, ...]:
        """A robot in MuJoCo serves no services (Gazebo's are not simulated)."""
        return ()

    def call(self, name: str, request: Mapping[str, object]) -> ServiceResult:
        """There is no service to call: a caller should look in ``services`` first."""
        raise SimError(f"the robot world serves no service {name!r} (request {dict(request)!r})")

    def command(self, topic: str, linear: tuple[float, float, float] = (0.0, 0.0, 0.0), angular: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> bool:
        """A Twist received now on ``topic``; it takes effect on the next control tick. False if the base does not listen there."""
        if topic not in self._topics:
            return False
        self._latch.receive(self._time_ns, float(linear[0]), float(angular[2]))
        return True

    def advance_to(self, t_ns: int) -> list[Sample]:
        """Step physics to ``t_ns``; return the samples due in (previous time, ``t_ns``], in time order."""
        if t_ns < self._time_ns:
            raise SimError(f"cannot advance back in time: now {self._time_ns} ns, asked for {t_ns} ns")
        out, self._pending = self._pending, []
        self._run(t_ns, out, emit=True)
        return out

    def next_output_ns(self, topics: Collection[str] | None = None) -> int | None:
        """When the next sample (odometry, /tf, ground truth, a sensor or a scripted command) is due.

        With ``topics``, only samples on those topics (and scripted commands) count: a caller that delivers only
        to subscribers need not stop at the others, which come out of the next ``advance_to`` all the same.
        None when nothing asked about is due.
        """
        if self._pending:
            return self._pending[0].t_ns
        periods = self._output_periods if topics is None else {
            self._topic_periods[topic] for topic in topics if topic in self._topic_periods}
        due = [step_ns((self._k // period + 1) * period) for period in periods]
        if self._next_script < len(self._script):
            due.append(max(self._script[self._next_script][0], self._time_ns))
        return min(due, default=None)

    def state(self) -> dict[str, float]:
        """Named quantities now: true pose and body twist, wheel speeds (rad/s) and servo targets, the command in force."""
        truth = ground_truth(self.data)
        x, y, z, w = truth.orientation
        left, right = self._wheel_qvel
        return {
            "x": truth.position[0],
            "y": truth.position[1],
            "z": truth.position[2],
            "roll": math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y)),
            "pitch": math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x)))),
            "yaw": quaternion_yaw(truth.orientation),
            "vx": truth.linear[0],
            "vy": truth.linear[1],
            "vz": truth.linear[2],
            "wx": truth.angular[0],
            "wy": truth.angular[1],
            "wz": truth.angular[2],
            "wheel_left": float(self.data.qvel[left]),
            "wheel_right": float(self.data.qvel[right]),
            "wheel_left_target": self._wheel_targets[0],
            "wheel_right_target": self._wheel_targets[1],
            "command_linear": self._command[0],
            "command_angular": self._command[1],
        }

    # -- the loop ------------------------------------------------------------------------------------------------

    def _run(self, t_ns: int, out: list[Sample], emit: bool) -> None:
        """Process every event up to ``t_ns``: scripted commands first, then physics, then that step's ticks."""
        last = last_step_at(t_ns)
        while True:
            k = self._k + self._to_next_tick[self._k % self._cycle]
            if k > last:
                break
            self._apply_script(step_ns(k), out)
            mujoco.mj_step(self.model, self.data, nstep=k - self._k)
            self._k = k
            self._tick(k, out if emit else None)
        if last > self._k:
            mujoco.mj_step(self.model, self.data, nstep=last - self._k)
            self._k = last
        self._apply_script(t_ns, out)
        self._time_ns = t_ns

    def _apply_script(self, t_ns: int, out: list[Sample]) -> None:
        """Deliver the scripted commands due by ``t_ns`` (as if a node had published them then)."""
        while self._next_script < len(self._script) and self._script[self._next_script][0] <= t_ns:
            due_ns, command = self._script[self._next_script]
            self._next_script += 1
            topic = command.topic or self._topics[0]
            self._latch.receive(due_ns, command.linear[0], command.angular[2])
            out.append(CommandSample(due_ns, topic, command.linear, command.angular))

    def _tick(self, k: int, out: list[Sample] | None) -> None:
        """The driver, odometry, /tf, ground-truth and sensor ticks on step ``k``; samples go to ``out`` unless None."""
        t_ns = step_ns(k)
        if k % self._control_every == 0:
            self._command = self._latch.command_at(t_ns)
            rims = self._driver.tick(*self._command)
            radius = self.profile.geometry.wheel_radius  # the driver believes the nominal radius
            self._wheel_targets = (rims[0] / radius, rims[1] / radius)
            self.data.ctrl[self._wheel_ctrl[0]] = self._wheel_targets[0]
            self.data.ctrl[self._wheel_ctrl[1]] = self._wheel_targets[1]
        if k % self._odometry_every == 0:
            self._estimate = self._odometry.update(t_ns, self.data)
            if out is not None:
                odom = self.mode.odometry
                e = self._estimate
                out.append(OdometrySample(t_ns, odom.topic, odom.frame_id, odom.child_frame_id, e.position, e.orientation,
                                          e.linear, e.angular, self._pose_covariance, self._twist_covariance))
        if out is not None:
            if self._tf_every is not None and k % self._tf_every == 0:
                tf = self.mode.tf
                assert tf is not None
                out.append(TransformSample(t_ns, TF_TOPIC, tf.parent, tf.child, self._estimate.position, self._estimate.orientation))
            if k % self._truth_every == 0:
                truth = ground_truth(self.data)
                out.append(GroundTruthSample(t_ns, GROUND_TRUTH_TOPIC, GROUND_TRUTH_FRAME, self.mode.odometry.child_frame_id,
                                             truth.position, truth.orientation, truth.linear, truth.angular))
        for period, sensor in self._sensors:
            if k % period == 0:
                sample = sensor.sample(t_ns, self.data)  # the IMU differentiates velocity: it samples even unrecorded
                if out is not None:
                    out.append(sample)
