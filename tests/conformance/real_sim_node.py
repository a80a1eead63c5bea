#!/usr/bin/env python3
"""A minimal Gazebo stand-in for the real-ROS side of the conformance suite (runs under Debian's /usr/bin/python3).

It publishes /clock every 10 ms of sim time paced at 1x wall time, and /odom (nav_msgs/Odometry), /tf and /joint_states
at 30 Hz from a kinematic unicycle that integrates the last /cmd_vel, /imu at 200 Hz and an empty world's /scan
(all inf) at 5 Hz, as the TurtleBot3's Gazebo plugins fill them. It is driven by the harness (real_ros.py) over stdin/stdout:

stdin  ``watch <id> <pid> <shutdown_s|-> <end_s>``: the next new subscriber of /clock is that probe; its first clock
       tick is its time origin; SIGINT the pid at origin + shutdown_s; report ``end`` at origin + end_s.
stdout one JSON object per line: ``ready``, ``first_clock``, ``sigint``, ``end``, ``cmd`` (every /cmd_vel received,
       stamped with the last /clock value published), ``error``.
"""
from __future__ import annotations

import json
import math
import os
import signal
import sys
import threading
import time

import genpy
import rospy
from geometry_msgs.msg import TransformStamped, Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Imu, JointState, LaserScan
from tf2_msgs.msg import TFMessage

CLOCK_NS = 10_000_000
ODOM_HZ = 30  # also /joint_states, as gazebo_ros_diff_drive publishes them
IMU_HZ = 200
SCAN_HZ = 5
NS = 1_000_000_000
WHEEL_RADIUS, WHEEL_SEPARATION = 0.033, 0.287  # TurtleBot3 Waffle

_out_lock = threading.Lock()


def emit(**fields: object) -> None:
    with _out_lock:
        sys.stdout.write(json.dumps(fields) + "\n")
        sys.stdout.flush()


class Sim:
    def __init__(self, start_ns: int) -> None:
        self.lock = threading.Lock()
        self.clock_ns = 0            # last /clock value published
        self.cmd = (0.0, 0.0)        # vx, wz
        self.x = self.y = self.yaw = 0.0
        self.wheels = [0.0, 0.0]  # left, right joint angles
        self.integrated_ns = start_ns
        self.seq = 0
        self.watch: dict | None = None
        self.seen_connections: set[int] = set()

    # ---- /cmd_vel ------------------------------------------------------------------------------------------
    def on_cmd(self, msg: Twist) -> None:
        with self.lock:
            t = self.clock_ns
            self.integrate(t)
            self.cmd = (msg.linear.x, msg.angular.z)
            watch = self.watch["id"] if self.watch else None
        emit(ev="cmd", watch=watch, t_ns=t, callerid=msg._connection_header.get("callerid", ""),
             linear=[msg.linear.x, msg.linear.y, msg.linear.z], angular=[msg.angular.x, msg.angular.y, msg.angular.z])

    def integrate(self, t_ns: int) -> None:
        dt = (t_ns - self.integrated_ns) / NS
        if dt <= 0:
            return
        vx, wz = self.cmd
        self.wheels[0] += (vx - wz * WHEEL_SEPARATION / 2) / WHEEL_RADIUS * dt
        self.wheels[1] += (vx + wz * WHEEL_SEPARATION / 2) / WHEEL_RADIUS * dt
        if abs(wz) < 1e-12:
            self.x += vx * dt * math.cos(self.yaw)
            self.y += vx * dt * math.sin(self.yaw)
        else:
            yaw2 = self.yaw + wz * dt
            self.x += vx / wz * (math.sin(yaw2) - math.sin(self.yaw))
            self.y -= vx / wz * (math.cos(yaw2) - math.cos(self.yaw))
            self.yaw = yaw2
        self.integrated_ns = t_ns

    # ---- stdin control -------------------------------------------------------------------------------------
    def control(self) -> None:
        for line in sys.stdin:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "watch":
                with self.lock:
                    self.watch = {"id": parts[1], "pid": int(parts[2]),
                                  "shutdown": None if parts[3] == "-" else float(parts[3]),
                                  "end": float(parts[4]), "origin": None, "sigint_sent": False, "ended": False}
            elif parts[0] == "unwatch":
                with self.lock:
                    self.watch = None
            elif parts[0] == "quit":
                rospy.signal_shutdown("quit")
                return

    # ---- the paced loop ------------------------------------------------------------------------------------
    def run(self, start_ns: int, clock_pub, odom_pub, tf_pub, sensor_pubs) -> None:
        next_clock = start_ns
        # the next tick of each rate at or after start
        k_odom, k_imu, k_scan = (-(-start_ns * hz // NS) for hz in (ODOM_HZ, IMU_HZ, SCAN_HZ))
        wall0 = time.monotonic()
        emit(ev="ready", t_ns=start_ns)
        while not rospy.is_shutdown():
            t_odom, t_imu, t_scan = k_odom * NS // ODOM_HZ, k_imu * NS // IMU_HZ, k_scan * NS // SCAN_HZ
            t = min(next_clock, t_odom, t_imu, t_scan)
            delay = wall0 + (t - start_ns) / NS - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            if t == next_clock:
                self.before_clock(t, clock_pub)
                with self.lock:
                    self.clock_ns = t
                clock_pub.publish(Clock(clock=genpy.Time(0, t)))
                self.after_clock(t)
                next_clock += CLOCK_NS
            if t == t_odom:
                self.publish_odom(t, odom_pub, tf_pub)
                self.publish_joints(t, sensor_pubs["joint_states"])
                k_odom += 1
            if t == t_imu:
                self.publish_imu(t, sensor_pubs["imu"])
                k_imu += 1
            if t == t_scan:
                self.publish_scan(t, sensor_pubs["scan"])
                k_scan += 1

    def before_clock(self, t: int, clock_pub) -> None:
        conns = {id(c) for c in list(clock_pub.impl.connections or ())}
        with self.lock:
            new = conns - self.seen_connections
            self.seen_connections |= conns
            watch = self.watch
            if watch is None or watch["origin"] is not None or not new:
                return
            # The probe's /clock subscriber has connected: this tick is the first clock it receives.
            watch["origin"] = t
        emit(ev="first_clock", watch=watch["id"], t_ns=t)

    def after_clock(self, t: int) -> None:
        with self.lock:
            watch = self.watch
            if watch is None or watch["origin"] is None:
                return
            rel = t - watch["origin"]
            if watch["shutdown"] is not None and not watch["sigint_sent"] and rel >= round(watch["shutdown"] * NS):
                watch["sigint_sent"] = True
                try:
                    os.kill(watch["pid"], signal.SIGINT)
                    emit(ev="sigint", watch=watch["id"], t_ns=t)
                except ProcessLookupError:
                    emit(ev="sigint_missed", watch=watch["id"], t_ns=t)
            if not watch["ended"] and rel >= round(watch["end"] * NS):
                watch["ended"] = True
                emit(ev="end", watch=watch["id"], t_ns=t)

    def publish_odom(self, t: int, odom_pub, tf_pub) -> None:
        with self.lock:
            self.integrate(t)
            x, y, yaw, (vx, wz) = self.x, self.y, self.yaw, self.cmd
            self.seq += 1
            seq = self.seq
        stamp = genpy.Time(0, t)
        qz, qw = math.sin(yaw / 2), math.cos(yaw / 2)
        odom = Odometry()
        odom.header.seq = seq
        odom.header.stamp = stamp
        odom.header.frame_id = "odom"
        odom.child_frame_id = "base_footprint"
        odom.pose.pose.position.x, odom.pose.pose.position.y = x, y
        odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = qz, qw
        odom.twist.twist.linear.x, odom.twist.twist.angular.z = vx, wz
        odom_pub.publish(odom)
        tr = TransformStamped()
        tr.header.seq = seq
        tr.header.stamp = stamp
        tr.header.frame_id = "odom"
        tr.child_frame_id = "base_footprint"
        tr.transform.translation.x, tr.transform.translation.y = x, y
        tr.transform.rotation.z, tr.transform.rotation.w = qz, qw
        tf_pub.publish(TFMessage(transforms=[tr]))


    def publish_imu(self, t: int, pub) -> None:
        with self.lock:
            self.integrate(t)
            yaw, wz = self.yaw, self.cmd[1]
        msg = Imu()
        msg.header.stamp, msg.header.frame_id = genpy.Time(0, t), "imu_link"
        msg.orientation.z, msg.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        msg.angular_velocity.z = wz
        msg.linear_acceleration.z = 9.81
        pub.publish(msg)

    def publish_joints(self, t: int, pub) -> None:
        with self.lock:
            self.integrate(t)
            wheels = list(self.wheels)
        msg = JointState(name=["wheel_left_joint", "wheel_right_joint"], position=wheels)
        msg.header.stamp = genpy.Time(0, t)
        pub.publish(msg)

    def publish_scan(self, t: int, pub) -> None:
        msg = LaserScan(angle_min=0.0, angle_max=6.28319, angle_increment=6.28319 / 359, range_min=0.12,
                        range_max=3.5, ranges=[math.inf] * 360, intensities=[0.0] * 360)
        msg.header.stamp, msg.header.frame_id = genpy.Time(0, t), "base_scan"
        pub.publish(msg)


def main() -> None:
    start_ns = int(round(float(sys.argv[1]) * NS)) if len(sys.argv) > 1 else NS
    # Our own time is the wall clock: this node must not subscribe to the /clock it publishes.
    rospy.init_node("gazebo", disable_rostime=True, disable_signals=True)  # callerid /gazebo, as in Gazebo
    sim = Sim(start_ns)
    clock_pub = rospy.Publisher("/clock", Clock, queue_size=10)
    odom_pub = rospy.Publisher("/odom", Odometry, queue_size=10)
    tf_pub = rospy.Publisher("/tf", TFMessage, queue_size=10)
    sensor_pubs = {"imu": rospy.Publisher("/imu", Imu, queue_size=10),
                   "joint_states": rospy.Publisher("/joint_states", JointState, queue_size=10),
                   "scan": rospy.Publisher("/scan", LaserScan, queue_size=10)}
    rospy.Subscriber("/cmd_vel", Twist, sim.on_cmd, queue_size=100)
    threading.Thread(target=sim.control, daemon=True).start()
    try:
        sim.run(start_ns, clock_pub, odom_pub, tf_pub, sensor_pubs)
    except Exception as exc:  # noqa: BLE001 - reported to the harness, which fails the run
        emit(ev="error", message=f"{type(exc).__name__}: {exc}")
        raise


if __name__ == "__main__":
    main()
