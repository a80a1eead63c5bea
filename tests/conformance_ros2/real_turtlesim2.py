#!/usr/bin/env python3
"""A real-rclpy model of Jazzy's turtlesim_node, the real side of the turtlesim conformance probes (ROS 2 venv).

Written for this suite from how ros/ros_tutorials rolling 1.8.2 (what Jazzy ships) behaves, not from its code: a
16 ms update with dt 0.016 on the sim clock (at 1x, the Qt timer's wall period); queued teleports first; then the
rotate_absolute goal (cancel -> CANCELED and stop; else feedback ``remaining``, result ``delta``, SUCCEEDED within
0.02 rad and stop, or turn at 1 rad/s the short way, which refreshes the command time); then a command older than
1 s is zeroed; then θ += ω dt (wrapped with turtle.hpp's PI), x/y move along the new θ, the turtle is clamped to the
499/45 m canvas (a float) with the "Oh no! I hit the wall!" warning in the window's coordinates (y down), and the pose is
published. Commands set the velocity (linear.y only while ``holonomic``) and abort a running goal; a new goal aborts
the running one. Services answer as rclcpp answers a callback that returns false: with the (empty) response, the
error only logged. Parameters ``background_r/g/b`` (0..255) and ``holonomic`` are declared with their ranges.
Not modelled: the path picture and so the colour sensor (published white: nothing painted); a killed turtle's
endpoints stay on the graph, unused, and serve a turtle spawned again under its name (destroying them in a service
callback made rclpy 7.1's multi-threaded executor die with InvalidHandle "cannot use Destroyable because destruction
was requested").

It publishes /clock every 10 ms of sim time itself and takes the harness's control lines on stdin as
real_robot2.py does (watch/origin/unwatch), recording what arrives on /turtle1/cmd_vel.
"""
from __future__ import annotations

import argparse
import math
import signal
import struct
import threading
import time

import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.context import Context
from rclpy.executors import MultiThreadedExecutor
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.signals import SignalHandlerOptions
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Color, Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

from real_robot2 import CLOCK_NS, NS, START_NS, Robot, emit, spin_in_thread, stamp

PI = 3.14159265
UPDATE_NS = 16_000_000
DT = 0.016
TIMEOUT_NS = NS
QOS = QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)


def f32(value: float) -> float:
    return struct.unpack("f", struct.pack("f", value))[0]


CANVAS_M = f32((500 - 1) / 45)  # the frame keeps its size in metres as a float


def normalize(angle: float) -> float:
    return angle - 2 * PI * math.floor((angle + PI) / (2 * PI))


class Turtle:
    """One turtle: its state in window coordinates (y down), its endpoints on the node, its running goal."""

    def __init__(self, sim: TurtleSim, name: str) -> None:
        self.sim, self.name = sim, name
        self.goal = None
        self.ended: dict[bytes, tuple[threading.Event, RotateAbsolute.Result]] = {}  # by goal id
        self.place(0.0, 0.0, 0.0)
        node, group = sim.node, sim.group
        self.endpoints = [  # kept for the turtle's life and after (see the module docstring)
            node.create_subscription(Twist, f"{name}/cmd_vel", self.on_command, QOS),
            node.create_service(SetPen, f"{name}/set_pen", self.set_pen),
            node.create_service(TeleportAbsolute, f"{name}/teleport_absolute", self.teleport_absolute),
            node.create_service(TeleportRelative, f"{name}/teleport_relative", self.teleport_relative),
        ]
        self.pose_pub = node.create_publisher(Pose, f"{name}/pose", QOS)
        self.color_pub = node.create_publisher(Color, f"{name}/color_sensor", QOS)
        self.action = ActionServer(node, RotateAbsolute, f"{name}/rotate_absolute", self.execute,
                                   goal_callback=lambda _goal: GoalResponse.ACCEPT,
                                   cancel_callback=lambda _handle: CancelResponse.ACCEPT,
                                   handle_accepted_callback=self.accepted, callback_group=group)

    def place(self, x: float, y: float, theta: float) -> None:
        """Where spawnTurtle puts a new turtle: at rest, pen down, no goal."""
        if self.goal is not None:
            self.end_goal("abort")
        self.x, self.y, self.theta = x, f32(CANVAS_M - y), theta  # float arithmetic, as the frame's
        self.vx = self.vy = self.w = 0.0
        self.pen_on = True
        self.last_command_ns = self.sim.now_ns
        self.teleports: list[tuple[bool, float, float, float]] = []
        self.start_theta = 0.0
        self.result = RotateAbsolute.Result()

    # ---- callbacks (executor threads) -------------------------------------------------------------------
    def on_command(self, msg: Twist) -> None:
        if self.name == "turtle1":
            self.sim.recorder.on_command(msg)
        with self.sim.lock:
            self.last_command_ns = self.sim.now_ns
            self.vx = msg.linear.x
            if self.sim.node.get_parameter("holonomic").value:
                self.vy = msg.linear.y
            self.w = msg.angular.z
            if self.goal is not None:
                self.sim.log.warn("Velocity command received during rotation goal. Aborting goal")
                self.end_goal("abort")

    def set_pen(self, request, response):
        with self.sim.lock:
            self.pen_on = not request.off
        return response

    def teleport_absolute(self, request, response):
        with self.sim.lock:
            self.teleports.append((False, request.x, request.y, request.theta))
        return response

    def teleport_relative(self, request, response):
        with self.sim.lock:
            self.teleports.append((True, request.linear, 0.0, request.angular))
        return response

    def accepted(self, handle) -> None:
        with self.sim.lock:
            if self.goal is not None:
                self.sim.log.warn("Rotation goal received before a previous goal finished. Aborting previous goal")
                self.end_goal("abort")
            self.goal, self.start_theta = handle, self.theta
            self.result = RotateAbsolute.Result()
            self.ended[bytes(handle.goal_id.uuid)] = (threading.Event(), self.result)
        handle.execute()

    def execute(self, handle):
        done, result = self.ended[bytes(handle.goal_id.uuid)]
        while not done.wait(0.05):
            if not rclpy.ok(context=self.sim.node.context):
                break
        with self.sim.lock:
            del self.ended[bytes(handle.goal_id.uuid)]
        return result

    def end_goal(self, how: str) -> None:
        """Set the running goal's terminal state (the caller holds the lock) and release its execute callback with
        the result as it stood (the goal's own result object: a new goal gets a new one)."""
        getattr(self.goal, how)()
        self.ended[bytes(self.goal.goal_id.uuid)][0].set()
        self.goal = None

    # ---- the update (the paced loop, lock held) -------------------------------------------------------------
    def update(self, now_ns: int) -> None:
        for relative, a, b, theta in self.teleports:
            if relative:
                self.theta += theta
                self.x += math.cos(self.theta) * a
                self.y -= math.sin(self.theta) * a
            else:
                self.x, self.y, self.theta = a, max(0.0, CANVAS_M - b), theta
        self.teleports.clear()
        if self.goal is not None:
            self.step_goal(now_ns)
        if now_ns - self.last_command_ns > TIMEOUT_NS:
            self.vx = self.vy = self.w = 0.0
        self.theta = normalize(self.theta + self.w * DT)
        self.x += math.cos(self.theta) * self.vx * DT - math.sin(self.theta) * self.vy * DT
        self.y -= math.cos(self.theta) * self.vy * DT + math.sin(self.theta) * self.vx * DT
        if not (0 <= self.x <= CANVAS_M and 0 <= self.y <= CANVAS_M):
            self.sim.log.warn(f"Oh no! I hit the wall! (Clamping from [x={self.x:f}, y={self.y:f}])")
        self.x = min(max(self.x, 0.0), CANVAS_M)
        self.y = min(max(self.y, 0.0), CANVAS_M)
        self.pose_pub.publish(Pose(x=self.x, y=CANVAS_M - self.y, theta=self.theta,
                                   linear_velocity=math.hypot(self.vx, self.vy), angular_velocity=self.w))
        self.color_pub.publish(Color(r=255, g=255, b=255))

    def step_goal(self, now_ns: int) -> None:
        if self.goal.is_cancel_requested:
            self.sim.log.info("Rotation goal canceled")
            self.end_goal("canceled")
            self.vx = self.vy = self.w = 0.0
            return
        target = normalize(self.goal.request.theta)
        remaining = normalize(target - f32(self.theta))
        self.result.delta = normalize(f32(self.start_theta - self.theta))
        self.goal.publish_feedback(RotateAbsolute.Feedback(remaining=remaining))
        if abs(normalize(f32(self.theta) - target)) < 0.02:
            self.sim.log.info("Rotation goal completed successfully")
            self.end_goal("succeed")
            self.vx = self.vy = self.w = 0.0
        else:
            self.vx = self.vy = 0.0
            self.w = -1.0 if remaining < 0.0 else 1.0
            self.last_command_ns = now_ns


class TurtleSim:
    """The frame: turtles by name, the node's services and parameters; `update` every 16 ms of sim time."""

    def __init__(self, node, recorder: Robot) -> None:
        self.node, self.recorder, self.log = node, recorder, node.get_logger()
        self.lock = threading.RLock()
        self.group = ReentrantCallbackGroup()
        self.now_ns = START_NS
        self.turtles: dict[str, Turtle] = {}
        self.made: dict[str, Turtle] = {}  # every turtle ever made, alive or not: its endpoints are reused
        self.counter = 0
        for c, colour in (("r", "Red"), ("g", "Green"), ("b", "Blue")):
            node.declare_parameter(f"background_{c}", {"r": 69, "g": 86, "b": 255}[c], ParameterDescriptor(
                description=f"{colour} channel of the background color",
                integer_range=[IntegerRange(from_value=0, to_value=255, step=1)]))
        node.declare_parameter("holonomic", False,
                               ParameterDescriptor(description="If true, then turtles will be holonomic"))
        node.create_service(Empty, "clear", self.clear)
        node.create_service(Empty, "reset", self.reset)
        node.create_service(Spawn, "spawn", self.spawn_service)
        node.create_service(Kill, "kill", self.kill)
        self.log.info(f"Starting turtlesim with node name {node.get_fully_qualified_name()}")
        self.spawn("", CANVAS_M / 2.0, CANVAS_M / 2.0, 0.0)

    def spawn(self, name: str, x: float, y: float, theta: float) -> str:
        if not name:
            while True:
                self.counter += 1
                name = f"turtle{self.counter}"
                if name not in self.turtles:
                    break
        elif name in self.turtles:
            return ""
        x, y, theta = f32(x), f32(y), f32(theta)
        if name not in self.made:
            self.made[name] = Turtle(self, name)
        self.made[name].place(x, y, theta)
        self.turtles[name] = self.made[name]
        self.log.info(f"Spawning turtle [{name}] at x=[{x:f}], y=[{y:f}], theta=[{theta:f}]")
        return name

    def spawn_service(self, request, response):
        with self.lock:
            response.name = self.spawn(request.name, request.x, request.y, request.theta)
        if not response.name:
            self.log.error(f"A turtle named [{request.name}] already exists")
        return response

    def kill(self, request, response):
        with self.lock:
            turtle = self.turtles.pop(request.name, None)
        if turtle is None:
            self.log.error(f"Tried to kill turtle [{request.name}], which does not exist")
        return response

    def clear(self, request, response):
        self.log.info("Clearing turtlesim.")
        return response

    def reset(self, request, response):
        self.log.info("Resetting turtlesim.")
        with self.lock:
            self.turtles, self.counter = {}, 0
            self.spawn("", CANVAS_M / 2.0, CANVAS_M / 2.0, 0.0)
        return response

    def update(self, now_ns: int) -> None:
        with self.lock:
            self.now_ns = now_ns
            for turtle in list(self.turtles.values()):
                turtle.update(now_ns)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--speed", type=float, default=1.0, help="sim seconds per wall second")
    speed = parser.parse_args().speed
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    recorder = Robot()
    clock_ctx, ctx = Context(), Context()
    for c in (clock_ctx, ctx):
        rclpy.init(context=c, signal_handler_options=SignalHandlerOptions.NO)
    clock_node = rclpy.create_node("turtlesim_clock", context=clock_ctx)
    node = rclpy.create_node("turtlesim", context=ctx,
                             parameter_overrides=[Parameter("use_sim_time", Parameter.Type.BOOL, True)])
    clock_pub = clock_node.create_publisher(Clock, "/clock", 10)
    sim = TurtleSim(node, recorder)
    executor = MultiThreadedExecutor(num_threads=4, context=ctx)
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    spin_in_thread(clock_node)
    threading.Thread(target=recorder.control, daemon=True).start()
    next_clock, next_update = START_NS, START_NS + UPDATE_NS
    wall0 = time.monotonic()
    emit(ev="ready", t_ns=START_NS)
    while True:
        t = min(next_clock, next_update)
        delay = wall0 + (t - START_NS) / NS / speed - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        if t == next_clock:
            with recorder.lock:
                recorder.clock_ns = t
            clock_pub.publish(Clock(clock=stamp(t)))
            recorder.after_clock(t)
            next_clock += CLOCK_NS
        if t == next_update:
            sim.update(t)
            next_update += UPDATE_NS


if __name__ == "__main__":
    main()
