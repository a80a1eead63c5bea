#!/usr/bin/env python3
"""A small real rclpy robot for the real side of the ROS 2 conformance suite (runs in the ROS 2 venv).

It publishes /clock every 10 ms of sim time (paced at `--speed` x wall) and /odom (nav_msgs/Odometry) at 30 Hz, as
the Jazzy TurtleBot3's gz DiffDrive plugin does (``odom_publisher_frequency`` 30), from a kinematic unicycle driven
by the last command on /cmd_vel. It takes both command types there: TwistStamped (Jazzy) and Twist (Humble). One
DDS participant refuses two types on one topic, so the Twist subscriber lives in a second rclpy Context.
It is driven by the harness (real_ros2.py) over stdin, one command a line:

``watch <id> <pgid> <record.json>``  the commands received from now on belong to that probe
``origin <t_ns> <shutdown_ns|-> <end_ns>``  the probe's origin (its #REF); SIGINT the process group at origin +
                                    shutdown; report ``end`` at origin + end
``unwatch``                          write the record (time, type and values of each command received) and forget

and answers on stdout with one JSON object a line: ``ready``, ``sigint``, ``end``, ``unwatched``, ``error``.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import signal
import sys
import threading
import time

import rclpy
from builtin_interfaces.msg import Time as TimeMsg
from geometry_msgs.msg import Twist, TwistStamped
from nav_msgs.msg import Odometry
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.signals import SignalHandlerOptions
from rosgraph_msgs.msg import Clock

CLOCK_NS = 10_000_000
ODOM_HZ = 30
NS = 1_000_000_000
START_NS = NS  # the world has been running for a second when the harness starts probes

_out_lock = threading.Lock()


def emit(**fields: object) -> None:
    with _out_lock:
        sys.stdout.write(json.dumps(fields) + "\n")
        sys.stdout.flush()


def stamp(t_ns: int) -> TimeMsg:
    return TimeMsg(sec=t_ns // NS, nanosec=t_ns % NS)


class Robot:
    """The unicycle, the watched probe and what it sent; shared by the executor threads and the paced loop."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.clock_ns = START_NS
        self.integrated_ns = START_NS
        self.cmd = (0.0, 0.0)
        self.x = self.y = self.yaw = 0.0
        self.watch: dict | None = None

    def on_command(self, msg: Twist | TwistStamped) -> None:
        twist = msg.twist if isinstance(msg, TwistStamped) else msg
        kind = "geometry_msgs/msg/TwistStamped" if isinstance(msg, TwistStamped) else "geometry_msgs/msg/Twist"
        with self.lock:
            t = self.clock_ns
            self.integrate(t)
            self.cmd = (twist.linear.x, twist.angular.z)
            if self.watch is not None:
                self.watch["commands"].append({
                    "t_ns": t, "wall": time.time(), "type": kind, "after_sigint": self.watch["sigint_ns"] is not None,
                    "linear": [twist.linear.x, twist.linear.y, twist.linear.z],
                    "angular": [twist.angular.x, twist.angular.y, twist.angular.z]})

    def integrate(self, t_ns: int) -> None:
        dt = (t_ns - self.integrated_ns) / NS
        if dt <= 0:
            return
        vx, wz = self.cmd
        if abs(wz) < 1e-12:
            self.x += vx * dt * math.cos(self.yaw)
            self.y += vx * dt * math.sin(self.yaw)
        else:
            yaw2 = self.yaw + wz * dt
            self.x += vx / wz * (math.sin(yaw2) - math.sin(self.yaw))
            self.y -= vx / wz * (math.cos(yaw2) - math.cos(self.yaw))
            self.yaw = yaw2
        self.integrated_ns = t_ns

    def odometry(self, t_ns: int) -> Odometry:
        with self.lock:
            self.integrate(t_ns)
            x, y, yaw, (vx, wz) = self.x, self.y, self.yaw, self.cmd
        odom = Odometry()
        odom.header.stamp = stamp(t_ns)
        odom.header.frame_id = "odom"
        odom.child_frame_id = "base_footprint"
        odom.pose.pose.position.x, odom.pose.pose.position.y = x, y
        odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        odom.twist.twist.linear.x, odom.twist.twist.angular.z = vx, wz
        return odom

    # ---- harness control -----------------------------------------------------------------------------------
    def control(self) -> None:
        for line in sys.stdin:
            parts = line.split()
            if not parts:
                continue
            with self.lock:
                if parts[0] == "watch":
                    self.watch = {"id": parts[1], "pgid": int(parts[2]), "path": parts[3], "origin_ns": None,
                                  "shutdown_ns": None, "end_ns": None, "sigint_ns": None, "ended": False,
                                  "commands": []}
                elif parts[0] == "origin" and self.watch is not None:
                    origin = int(parts[1])
                    self.watch["origin_ns"] = origin
                    self.watch["shutdown_ns"] = None if parts[2] == "-" else origin + int(parts[2])
                    self.watch["end_ns"] = origin + int(parts[3])
                elif parts[0] == "unwatch" and self.watch is not None:
                    watch, self.watch = self.watch, None
                    with open(watch.pop("path"), "w", encoding="utf-8") as f:
                        json.dump(watch, f)
                    emit(ev="unwatched", watch=watch["id"])

    def after_clock(self, t_ns: int) -> None:
        """Ctrl+C and the end of the run fall on /clock ticks, as the harness asked."""
        with self.lock:
            watch = self.watch
            if watch is None or watch["origin_ns"] is None:
                return
            if watch["shutdown_ns"] is not None and watch["sigint_ns"] is None and t_ns >= watch["shutdown_ns"]:
                watch["sigint_ns"] = t_ns
                try:
                    os.killpg(watch["pgid"], signal.SIGINT)
                    emit(ev="sigint", watch=watch["id"], t_ns=t_ns)
                except ProcessLookupError:
                    emit(ev="sigint_missed", watch=watch["id"], t_ns=t_ns)
            if not watch["ended"] and t_ns >= watch["end_ns"]:
                watch["ended"] = True
                emit(ev="end", watch=watch["id"], t_ns=t_ns)


def spin_in_thread(node) -> None:
    executor = SingleThreadedExecutor(context=node.context)
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--speed", type=float, default=1.0, help="sim seconds per wall second")
    speed = parser.parse_args().speed
    robot = Robot()
    # The harness stops the robot with SIGTERM; rclpy's handlers would turn that into a slow orderly shutdown.
    contexts = [Context(), Context()]
    for ctx in contexts:
        rclpy.init(context=ctx, signal_handler_options=SignalHandlerOptions.NO)
    node = rclpy.create_node("robot", context=contexts[0])  # wall clock: it must not follow the /clock it publishes
    twist_node = rclpy.create_node("robot_twist", context=contexts[1])
    clock_pub = node.create_publisher(Clock, "/clock", 10)
    odom_pub = node.create_publisher(Odometry, "/odom", 10)
    node.create_subscription(TwistStamped, "/cmd_vel", robot.on_command, 100)
    twist_node.create_subscription(Twist, "/cmd_vel", robot.on_command, 100)
    for n in (node, twist_node):
        spin_in_thread(n)
    threading.Thread(target=robot.control, daemon=True).start()

    next_clock, k_odom = START_NS, -(-START_NS * ODOM_HZ // NS)
    wall0 = time.monotonic()
    emit(ev="ready", t_ns=START_NS)
    try:
        while True:
            t_odom = k_odom * NS // ODOM_HZ
            t = min(next_clock, t_odom)
            delay = wall0 + (t - START_NS) / NS / speed - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            if t == next_clock:
                with robot.lock:
                    robot.clock_ns = t
                clock_pub.publish(Clock(clock=stamp(t)))
                robot.after_clock(t)
                next_clock += CLOCK_NS
            if t == t_odom:
                odom_pub.publish(robot.odometry(t))
                k_odom += 1
    except Exception as exc:  # noqa: BLE001 - reported to the harness, which fails the run
        emit(ev="error", message=f"{type(exc).__name__}: {exc}")
        raise


if __name__ == "__main__":
    main()
