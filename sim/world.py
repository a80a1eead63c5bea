"""The world: one robot in MuJoCo, its base driver and odometry, advanced in exact integer-nanosecond sim time.

Physics steps at 600 Hz (``sim.clock``). Between ticks it is stepped in one ``mj_step(nstep=n)`` batch; Python runs
only on ticks: the control tick (latch the command, run the base driver, set the servo targets), the odometry and /tf
ticks, the 50 Hz ground truth and the sensors. What is due on each step of the ticks' common cycle is planned once, and
each tick reads the state once as plain lists. A world is built already run to its start time (the robot has been
standing there, waiting): physics runs until the robot has settled (``SETTLE_NS``), and a robot at rest then waits
without physics, since stepping it further only creeps it by nanometres. The settled state is kept per process, so
the next world with the same robot, pose and obstacles skips the wait, whatever its start time.
Same scenario → same bits, on one machine and MuJoCo version.
"""
from __future__ import annotations

import copy
import math
from collections import OrderedDict
from collections.abc import Collection, Mapping
from dataclasses import dataclass

import mujoco
import numpy as np

from sim.base_driver import BaseDriver, CommandLatch, make_driver
from sim.clock import last_step_at, step_ns, steps_per_tick
from sim.model import build_model
from sim.odometry import Estimate, WheelOdometry, WorldPoseOdometry, ground_truth, quaternion_yaw
from sim.profile import RobotProfile, covariance_matrix, load_robot
from sim.samples import (DEFAULT_QOS, CommandSample, ContactSample, GroundTruthSample, OdometrySample, Sample, ServiceResult,
                         TransformSample, WorldService, WorldTopic)
from sim.scenario import Scenario, ScenarioTimes
from sim.sensors import Imu, JointStates, Scanner

GROUND_TRUTH_HZ = 50  # above every odometry rate (30, 50 Hz); each sample is a recorded message
GROUND_TRUTH_TOPIC = "/ground_truth/odom"
GROUND_TRUTH_FRAME = "world"
TF_TOPIC = "/tf"
# The robot touching an obstacle, checked on every ground-truth tick (so a touch shorter than 20 ms may pass unseen).
CONTACT_TOPIC = "/rosgrade/contacts"
# What a robot state keeps of MuJoCo: time, qpos, qvel, act, warm start, controls and applied forces (mj_step reads
# nothing else; the derived quantities it leaves behind are recomputed by the next step before anything reads them).
_INTEGRATION = mujoco.mjtState.mjSTATE_INTEGRATION
NO_SCRIPT_NS = 2**63  # "the next scripted command" once there is none: later than any sim time
START_STATES = 16  # worlds at their start kept per process (each a _RobotState: a few hundred bytes of MuJoCo state)
# How long a new robot is simulated before it may wait at rest: the default start time. Measured from 2 s to 40 s at
# rest, every robot moved under 6e-9 m (qpos) and its speeds stayed under 1e-10, against REST_SPEED.
SETTLE_NS = 2_000_000_000
REST_SPEED = 1e-6  # m/s or rad/s: a robot whose every joint is slower than this waits without physics

Sensor = Imu | JointStates | Scanner
# What is due on one step of the cycle: control, odometry, /tf, ground truth, and the sensors in publication order.
Tick = tuple[bool, bool, bool, bool, tuple[Sensor, ...]]


NODE_NAME = "/gazebo"  # Gazebo's node publishes the simulated robot's topics

class SimError(Exception):
    """A world that cannot be built as asked, or a call that breaks the world's contract (e.g. going back in time)."""


@dataclass(frozen=True)
class _RobotState:
    """Everything about the robot that evolves, at one time: MuJoCo's integration state (``mj_getState``: time, qpos,
    qvel, act, warm start, controls, applied forces; all ``mj_step`` reads) and the world's own parts around it.

    The latch, driver and odometry hold only immutable values (rebound, never changed in place), so a shallow copy of
    each is independent of the world it came from; a sensor with state (the IMU) is kept as its attributes and put
    back into the world's own sensor, which the tick plan references.
    """

    physics: np.ndarray
    latch: CommandLatch
    driver: BaseDriver
    odometry: WheelOdometry | WorldPoseOdometry
    sensor_states: tuple[dict, ...]
    k: int
    time_ns: int
    command: tuple[float, float]
    wheel_targets: tuple[float, float]
    estimate: Estimate


# Worlds one nanosecond before their start, or settled (see SETTLE_NS), by everything that shapes them (_start_key);
# least recently used first.
_start_states: OrderedDict[str, _RobotState] = OrderedDict()


@dataclass(frozen=True)
class _Schedule:
    """The ticks of one set of heard sensors, repeating every ``cycle`` steps."""

    cycle: int
    to_next_tick: list[int]  # for each step of the cycle, the steps to the next tick
    plan: list[Tick]  # what is due on each step of the cycle
    unheard: tuple[tuple[int, Sensor], ...]  # (period, sensor) of the unheard sensors that keep state


@dataclass(frozen=True)
class Snapshot:
    """Everything a world's future depends on, at one time: ``World.restore`` makes the world continue from here
    bit for bit as it did the first time (the session's rollback of a speculative advance). The robot's state, and
    where the run is: the script's next command, samples not yet handed out, the heard sensors' tick plan."""

    robot: _RobotState
    next_script: int
    next_script_ns: int
    pending: tuple[Sample, ...]
    schedule: _Schedule


class World(ScenarioTimes):
    """One run of a robot: ``command`` it, ``advance_to`` a time, collect the samples it published on the way."""

    def __init__(self, scenario: Scenario, profile: RobotProfile | None = None, flavour: str = "ros1") -> None:
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
        obstacles = scenario.all_obstacles
        robot = build_model(self.profile, scenario.imperfections.wheel_radius_scale, obstacles)
        self.model = robot.model
        self.data = mujoco.MjData(self.model)
        # Obstacle geom -> what feedback calls it; empty on an open floor, where contacts are never looked at.
        self._obstacle_names = {geom: obstacle.name or f"{obstacle.kind} {i + 1}"
                                for i, (geom, obstacle) in enumerate(zip(robot.obstacle_geoms, obstacles))}
        # Views of MjData's buffers, which never move: the ticks read them without going through the binding.
        self._qpos, self._qvel, self._ctrl = self.data.qpos, self.data.qvel, self.data.ctrl
        self._state_size = mujoco.mj_stateSize(self.model, _INTEGRATION)
        self._wheel_qvel = robot.wheel_qvel
        self._wheel_ctrl = robot.wheel_ctrl
        sensors = self.mode.sensors
        start_ns = scenario.start_ns
        settled_ns = min(start_ns, SETTLE_NS)
        start_key = _start_key(self.profile, self.mode_name, scenario, settled_ns)
        saved = _start_states.get(start_key)
        self._odometry: WheelOdometry | WorldPoseOdometry
        pose = scenario.initial_pose
        self.data.qpos[:7] = (pose.x, pose.y, 0.0, math.cos(pose.yaw / 2), 0.0, 0.0, math.sin(pose.yaw / 2))
        qpos, qvel = self._qpos.tolist(), self._qvel.tolist()
        self._latch, self._driver = make_driver(self.mode, geometry)
        self._odometry = (
            WorldPoseOdometry()
            if self.mode.odometry.source == "world"
            else WheelOdometry(geometry.wheel_radius, geometry.wheel_separation, robot.wheel_qpos, 0, qpos)
        )
        imu = Imu(sensors.imu, self.model, 0, qvel) if sensors.imu is not None else None
        odometry, tf = self.mode.odometry, self.mode.tf
        self._odometry_names = (odometry.topic, odometry.frame_id, odometry.child_frame_id)
        self._tf_names = (TF_TOPIC, tf.parent, tf.child) if tf is not None else None
        self._truth_names = (GROUND_TRUTH_TOPIC, GROUND_TRUTH_FRAME, odometry.child_frame_id)
        self._pose_covariance = covariance_matrix(self.mode.odometry.pose_covariance)
        self._twist_covariance = covariance_matrix(self.mode.odometry.twist_covariance)
        self._control_every = steps_per_tick(self.mode.control_rate_hz)
        self._odometry_every = steps_per_tick(self.mode.odometry.rate_hz)
        self._tf_every = steps_per_tick(self.mode.tf.rate_hz) if self.mode.tf is not None else None
        self._truth_every = steps_per_tick(GROUND_TRUTH_HZ)
        self._sensors: list[tuple[int, Sensor]] = []
        if sensors.imu is not None:
            assert imu is not None
            self._sensors.append((steps_per_tick(sensors.imu.rate_hz), imu))
        if sensors.joint_states is not None:
            self._sensors.append((steps_per_tick(sensors.joint_states.rate_hz), JointStates(sensors.joint_states, robot)))
        # The scanner as the simulation of the nodes' ROS version publishes it (Jazzy's Waffle: 10 Hz, Noetic's: 5 Hz).
        self._scan = sensors.scan.for_flavour(flavour) if sensors.scan is not None else None
        if self._scan is not None:
            self._sensors.append((steps_per_tick(self._scan.rate_hz), Scanner(self._scan, robot, self.data, scenario.seed)))
        self._output_periods = tuple(
            p for p in (self._odometry_every, self._tf_every, self._truth_every, *(p for p, _ in self._sensors))
            if p is not None
        )
        self._topic_periods = {topic.topic: steps_per_tick(topic.rate_hz) for topic in self.publications}
        self._schedules: dict[tuple[int, ...], _Schedule] = {}
        self._schedule = self._schedule_for(self._sensors)

        self._script = [(start_ns + command.t_ns, command) for command in scenario.script]
        self._next_script = 0
        self._next_script_ns = self._script[0][0] if self._script else NO_SCRIPT_NS
        self._estimate: Estimate  # set by the odometry tick at step 0
        if saved is None:
            self._command = (0.0, 0.0)
            self._wheel_targets = (0.0, 0.0)
            self._k = 0
            self._time_ns = 0
            self._tick(0, 0, None)
            if settled_ns > 0:
                # The world has been running since 0, the robot waiting: nothing is scripted before the start.
                self._run(settled_ns - 1, [], emit=False)
                _remember(start_key, self._robot_state())
        else:
            _start_states.move_to_end(start_key)
            self._put_robot_state(saved)
        if start_ns > settled_ns:
            if max(map(abs, self._qvel.tolist())) < REST_SPEED:
                self._wait_at_rest(start_ns - 1)
            else:  # still moving (pushed by an obstacle, say): the wait is simulated to the end
                self._run(start_ns - 1, [], emit=False)
        # Commands scripted for the start itself come out of the first advance_to.
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
        if self._scan is not None:
            declared.append(WorldTopic(self._scan.topic, "sensor_msgs/LaserScan", self._scan.rate_hz,
                                       qos=(self._scan.reliability, "VOLATILE")))
        if self._obstacle_names:
            declared.append(WorldTopic(CONTACT_TOPIC, "std_msgs/String", GROUND_TRUTH_HZ, to_nodes=False))
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
    def command_qos(self) -> tuple[str, str]:
        """(reliability, durability) the base's ROS 2 command subscriber requests, in every mode: the Jazzy
        simulation's ros_gz_bridge (rclcpp::QoS(KeepLast(10))) and the real robot's turtlebot3_node (KeepLast(10))
        both ask for RELIABLE, VOLATILE, so a BEST_EFFORT publisher never reaches them."""
        return DEFAULT_QOS

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

    def repeat_command(self, t_ns: int) -> None:
        """The command in force was received again at ``t_ns`` (no later than now), the same values: what a run ahead
        of a node that repeats its command leaves to do, since only the base's timeout notices a repeat."""
        self._latch.renew(t_ns)

    def command_holds_until_ns(self) -> int | None:
        """The last time the command in force holds if no other comes: None when the base has no timeout."""
        return self._latch.holds_until_ns()

    @property
    def next_scripted_command_ns(self) -> int | None:
        """When the scenario's next scripted command is due (None: there is none left)."""
        return None if self._next_script_ns == NO_SCRIPT_NS else self._next_script_ns

    def listen(self, topics: Collection[str] | None) -> None:
        """Publish the sensor topics among ``topics`` only (None, the default: every sensor), from the next step on.

        A sensor nobody subscribes to changes nothing in the world, and at 200 Hz (a TurtleBot3's /imu) its samples
        cost more to encode and record than the physics costs to run; the session names what its nodes subscribe to.
        Odometry, /tf and ground truth are always published."""
        heard = None if topics is None else frozenset(topics)
        self._schedule = self._schedule_for([(p, sensor) for p, sensor in self._sensors
                                             if heard is None or sensor.topic in heard])

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
        truth = ground_truth(self._qpos.tolist(), self._qvel.tolist())
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

    def snapshot(self) -> Snapshot:
        """The world as it is now, to ``restore`` later (a few microseconds)."""
        return Snapshot(self._robot_state(), self._next_script, self._next_script_ns, tuple(self._pending),
                        self._schedule)

    def restore(self, snapshot: Snapshot) -> None:
        """Put the world back to ``snapshot`` (taken from this world): what follows is what followed it then."""
        self._put_robot_state(snapshot.robot)
        self._next_script, self._next_script_ns = snapshot.next_script, snapshot.next_script_ns
        self._pending, self._schedule = list(snapshot.pending), snapshot.schedule

    def _robot_state(self) -> _RobotState:
        physics = np.empty(self._state_size)
        mujoco.mj_getState(self.model, self.data, physics, _INTEGRATION)
        return _RobotState(physics, copy.copy(self._latch), copy.copy(self._driver), copy.copy(self._odometry),
                           tuple(dict(vars(sensor)) for _, sensor in self._sensors if sensor.keeps_state),
                           self._k, self._time_ns, self._command, self._wheel_targets, self._estimate)

    def _put_robot_state(self, state: _RobotState) -> None:
        """Make the robot as it was in ``state``: taken from this world, or from another of the same start key (the
        same robot, mode, obstacles and start; its sensors come in the same order)."""
        mujoco.mj_setState(self.model, self.data, state.physics, _INTEGRATION)
        self._latch, self._driver = copy.copy(state.latch), copy.copy(state.driver)
        self._odometry = copy.copy(state.odometry)
        for sensor, kept in zip((s for _, s in self._sensors if s.keeps_state), state.sensor_states):
            vars(sensor).update(kept)
        self._k, self._time_ns, self._command = state.k, state.time_ns, state.command
        self._wheel_targets, self._estimate = state.wheel_targets, state.estimate

    # -- the loop ------------------------------------------------------------------------------------------------

    def _schedule_for(self, sensors: list[tuple[int, Sensor]]) -> _Schedule:
        """The ticks with these sensors sampled (the others unheard), cached by which sensors they are."""
        key = tuple(i for i, entry in enumerate(self._sensors) if entry in sensors)
        if key not in self._schedules:
            periods = [p for p in (self._control_every, self._odometry_every, self._tf_every, self._truth_every)
                       if p is not None] + [p for p, _ in sensors]
            # The ticks repeat every `cycle` steps: for each step in the cycle, the distance to the next tick.
            cycle = math.lcm(*periods)
            ticks = [r for r in range(cycle) if any(r % p == 0 for p in periods)]
            to_next = [next((t for t in ticks if t > r), cycle) - r for r in range(cycle)]
            plan = [self._due_at(r, sensors) for r in range(cycle)]
            unheard = tuple(entry for entry in self._sensors if entry not in sensors and entry[1].keeps_state)
            self._schedules[key] = _Schedule(cycle, to_next, plan, unheard)
        return self._schedules[key]

    def _due_at(self, r: int, sensors: list[tuple[int, Sensor]]) -> Tick:
        """What is due on a step ``r`` (mod the cycle) after the start of a cycle."""
        return (r % self._control_every == 0, r % self._odometry_every == 0,
                self._tf_every is not None and r % self._tf_every == 0, r % self._truth_every == 0,
                tuple(sensor for period, sensor in sensors if r % period == 0))

    def _run(self, t_ns: int, out: list[Sample], emit: bool) -> None:
        """Process every event up to ``t_ns``: scripted commands first, then physics, then that step's ticks.

        An unheard sensor with state (the IMU) is not ticked at its rate: only its last sample time up to ``t_ns``
        matters, since the next sample someone hears differentiates against that one, so physics stops there."""
        last = last_step_at(t_ns)
        schedule = self._schedule
        model, data, to_next_tick, cycle = self.model, self.data, schedule.to_next_tick, schedule.cycle
        emitted = out if emit else None
        k = self._k
        observe = sorted(((last // p) * p, sensor) for p, sensor in schedule.unheard if (last // p) * p > k)
        while True:
            tick = k + to_next_tick[k % cycle]
            while observe and observe[0][0] < tick:
                at, sensor = observe.pop(0)
                mujoco.mj_step(model, data, nstep=at - k)
                self._k = k = at
                sensor.observe(step_ns(at), self._qvel.tolist())
            if tick > last:
                break
            tick_ns = step_ns(tick)
            if self._next_script_ns <= tick_ns:
                self._apply_script(tick_ns, out)
            mujoco.mj_step(model, data, nstep=tick - k)
            self._k = k = tick
            self._tick(k, tick_ns, emitted)
            while observe and observe[0][0] == tick:
                observe.pop(0)[1].observe(tick_ns, self._qvel.tolist())
        if last > k:
            mujoco.mj_step(model, data, nstep=last - k)
            self._k = last
        self._apply_script(t_ns, out)
        self._time_ns = t_ns

    def _wait_at_rest(self, t_ns: int) -> None:
        """Move a robot at rest, with no command, on to ``t_ns`` without stepping physics: its state stays as it is,
        and the ticks it skips would have changed nothing that is heard (odometry and the IMU differentiate against
        their last tick, whenever that was)."""
        k = last_step_at(t_ns)
        self.data.time += (k - self._k) * self.model.opt.timestep
        self._k, self._time_ns = k, t_ns

    def _apply_script(self, t_ns: int, out: list[Sample]) -> None:
        """Deliver the scripted commands due by ``t_ns`` (as if a node had published them then)."""
        while self._next_script_ns <= t_ns:
            due_ns, command = self._script[self._next_script]
            self._next_script += 1
            self._next_script_ns = (self._script[self._next_script][0] if self._next_script < len(self._script)
                                    else NO_SCRIPT_NS)
            topic = command.topic or self._topics[0]
            self._latch.receive(due_ns, command.linear[0], command.angular[2])
            out.append(CommandSample(due_ns, topic, command.linear, command.angular))

    def _tick(self, k: int, t_ns: int, out: list[Sample] | None) -> None:
        """The driver, odometry, /tf, ground-truth and sensor ticks on step ``k`` (at ``t_ns``); samples go to ``out``
        unless None."""
        control, odometry, tf, truth, sensors = self._schedule.plan[k % self._schedule.cycle]
        if control:
            self._command = self._latch.command_at(t_ns)
            rims = self._driver.tick(*self._command)
            radius = self.profile.geometry.wheel_radius  # the driver believes the nominal radius
            self._wheel_targets = left, right = (rims[0] / radius, rims[1] / radius)
            ctrl = self._ctrl
            ctrl[self._wheel_ctrl[0]] = left
            ctrl[self._wheel_ctrl[1]] = right
        qpos, qvel = self._qpos.tolist(), self._qvel.tolist()
        if odometry:
            self._estimate = e = self._odometry.update(t_ns, qpos, qvel)
            if out is not None:
                out.append(OdometrySample(t_ns, *self._odometry_names, e.position, e.orientation, e.linear, e.angular,
                                          self._pose_covariance, self._twist_covariance))
        if out is not None:
            if tf:
                assert self._tf_names is not None
                out.append(TransformSample(t_ns, *self._tf_names, self._estimate.position, self._estimate.orientation))
            if truth:
                g = ground_truth(qpos, qvel)
                out.append(GroundTruthSample(t_ns, *self._truth_names, g.position, g.orientation, g.linear, g.angular))
                if self._obstacle_names and self.data.ncon:
                    out.extend(self._contacts(t_ns))
        for sensor in sensors:
            if out is not None:
                out.append(sensor.sample(t_ns, qpos, qvel))
            else:
                sensor.observe(t_ns, qvel)  # the IMU differentiates velocity: it keeps its state unheard

    def _contacts(self, t_ns: int) -> list[ContactSample]:
        """The obstacles the robot touches now (from the contacts of the last physics step), each once, at its deepest
        point, in the order of the scenario's obstacles."""
        n = self.data.ncon
        geoms, dist, pos = self.data.contact.geom[:n], self.data.contact.dist[:n], self.data.contact.pos[:n]
        deepest: dict[int, int] = {}
        for i, (a, b) in enumerate(geoms.tolist()):
            obstacle = a if a in self._obstacle_names else b if b in self._obstacle_names else None
            if obstacle is not None and (obstacle not in deepest or dist[i] < dist[deepest[obstacle]]):
                deepest[obstacle] = i
        return [ContactSample(t_ns, CONTACT_TOPIC, self._obstacle_names[g], tuple(pos[i].tolist()), -float(dist[i]))
                for g, i in sorted(deepest.items())]


def _start_key(profile: RobotProfile, mode_name: str, scenario: Scenario, settled_ns: int) -> str:
    """Everything that shapes a world until it has settled at ``settled_ns`` (the script acts only from the start
    on); repr keeps every float's exact value, -0.0 included."""
    return repr((profile.model_dump(), mode_name, scenario.imperfections.wheel_radius_scale,
                 [obstacle.model_dump() for obstacle in scenario.all_obstacles], scenario.initial_pose.model_dump(),
                 settled_ns))


def _remember(key: str, state: _RobotState) -> None:
    """Keep ``state`` for ``key``, forgetting the least recently used start beyond ``START_STATES``."""
    _start_states[key] = state
    while len(_start_states) > START_STATES:
        _start_states.popitem(last=False)
