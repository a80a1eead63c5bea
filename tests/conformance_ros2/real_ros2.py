"""Run a probe node under REAL rclpy (Jazzy's, from PyPI's ros-jazzy-* wheels, Fast DDS) beside a real rclpy robot,
for the ROS 2 suite.

`ros2_env` is the one place that knows what it takes to run rclpy from the venv `.ci/ros2-venv` builds. `RealRos2`
holds one robot (`real_robot2.py`: /clock at 100 Hz, /odom at 30 Hz, records /cmd_vel) on a DDS domain id of its
own (claimed with a lock file, so parallel test runs on one machine never see each other's nodes) and runs probes
one after another with `run_probe`: the probe's ``#REF <sim s>`` line (printed once it has sim time) is its origin;
the robot sends Ctrl+C (SIGINT to the probe's process group) at origin + `shutdown_at` sim seconds, and the probe
is SIGKILLed at origin + `duration` or when its wall budget runs out. Every process is in its own group and is
killed on the way out.
"""
from __future__ import annotations

import fcntl
import json
import os
import queue
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

VENV = Path(os.environ.get("ROSGRADE_ROS2_VENV", "/opt/rosgrade-ros2-jazzy-venv"))
ROBOT_NODE = Path(__file__).resolve().parent / "real_robot2.py"
NS = 1_000_000_000
# Domain ids 1..100 keep Fast DDS's ports (7400 + 250 * id ...) in the ephemeral-free range.
DOMAIN_IDS = range(1, 101)
_REF = re.compile(r"^#REF (-?\d+\.\d+)\s*$")


class RealRos2Error(Exception):
    """The real-ROS 2 harness could not run (no venv, the robot did not come up, no free domain id)."""


def _site_packages(venv: Path) -> Path:
    found = sorted((venv / "lib").glob("python3*/site-packages"))
    if not found:
        raise RealRos2Error(f"no site-packages under {venv / 'lib'}")
    return found[0]


def ros2_env(domain_id: int, home: Path, venv: Path = VENV) -> dict[str, str]:
    """The environment a real rclpy node needs from the venv, on its own DDS domain, with nothing from this process.

    * LD_LIBRARY_PATH: the wheels' shared libraries (``ros_*.libs``, ``<venv>/lib``). The wheels' own .pth hook would
      compute the same and re-exec python; ``_ROS_WHEELS_BOOTSTRAP_COMPLETE`` skips that second start.
    * AMENT_PREFIX_PATH: the venv, where the wheels put ``share/ament_index`` (rmw and type support lookup).
    * RMW_IMPLEMENTATION: Fast DDS, named so that no other rmw a wheel may bring is picked.
    * ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST and a ROS_DOMAIN_ID per run: no traffic off the machine, and no
      cross-talk between test runs on it.
    * ROS_HOME/ROS_LOG_DIR under `home`: rcl's log files stay in the run's directory.
    * PYTHONUNBUFFERED: the harness reads ``#REF`` as it is printed, and a SIGKILLed probe loses no output.
    """
    site = _site_packages(venv)
    libs = [str(p) for p in sorted(site.glob("ros_*.libs")) if p.is_dir()] + [str(venv / "lib")]
    env = {k: os.environ[k] for k in ("LANG", "LC_ALL", "TZ", "TERM", "USER") if k in os.environ}
    env.setdefault("LANG", "C.UTF-8")
    env.update(
        PATH=f"{venv / 'bin'}:/usr/local/bin:/usr/bin:/bin",
        HOME=str(home), ROS_HOME=str(home / "ros_home"), ROS_LOG_DIR=str(home / "log"),
        VIRTUAL_ENV=str(venv), LD_LIBRARY_PATH=":".join(libs), _ROS_WHEELS_BOOTSTRAP_COMPLETE="1",
        AMENT_PREFIX_PATH=str(venv), RMW_IMPLEMENTATION="rmw_fastrtps_cpp",
        ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST", ROS_DOMAIN_ID=str(domain_id),
        PYTHONUNBUFFERED="1", PYTHONDONTWRITEBYTECODE="1",
    )
    return env


def venv_python(venv: Path = VENV) -> Path:
    return venv / "bin" / "python"


_unavailable: dict[Path, str | None] = {}


def unavailable_reason(venv: Path = VENV) -> str | None:
    """None when the venv runs rclpy and the message packages the suite uses; else why not (the tests' skip reason)."""
    if venv not in _unavailable:
        _unavailable[venv] = _probe_venv(venv)
    return _unavailable[venv]


def _probe_venv(venv: Path) -> str | None:
    python = venv_python(venv)
    if not python.exists():
        failed = venv / "INSTALL_FAILED"
        why = failed.read_text(encoding="utf-8", errors="replace").strip() if failed.exists() else ""
        return (f"real ROS 2 (rclpy) is not installed: no venv at {venv} (built by .ci/ros2-venv; ROSGRADE_ROS2_VENV "
                "chooses another)" + (f"; the install failed: {why}" if why else ""))
    home = Path(tempfile.mkdtemp(prefix="rosgrade-ros2-check-"))
    try:
        code = ("import rclpy, rclpy.executors; from geometry_msgs.msg import Twist, TwistStamped; "
                "from nav_msgs.msg import Odometry; from rosgraph_msgs.msg import Clock; "
                "rclpy.init(); n = rclpy.create_node('rosgrade_venv_check'); n.destroy_node(); rclpy.shutdown()")
        proc = subprocess.run([str(python), "-c", code], env=ros2_env(DOMAIN_IDS[-1], home, venv),
                              capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired, RealRos2Error) as exc:
        return f"real rclpy in {venv} does not run: {exc}"
    finally:
        shutil.rmtree(home, ignore_errors=True)
    if proc.returncode != 0:
        tail = (proc.stderr.strip().splitlines() or ["no output"])[-1]
        return f"real rclpy in {venv} does not run (exit {proc.returncode}): {tail}"
    return None


class DomainLock:
    """A ROS_DOMAIN_ID held for this process alone (an flock on a file per id, released when closed or on exit)."""

    def __init__(self, lock_dir: Path = Path(tempfile.gettempdir())) -> None:
        self.domain_id = -1
        self._file = None
        for domain_id in DOMAIN_IDS[:-1]:  # the last one is for the short venv check
            handle = open(lock_dir / f"rosgrade-ros2-domain-{domain_id}.lock", "w")
            try:
                fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                handle.close()
                continue
            self.domain_id, self._file = domain_id, handle
            return
        raise RealRos2Error("every ROS_DOMAIN_ID is taken by another test run")

    def close(self) -> None:
        if self._file is not None:
            self._file.close()
            self._file = None


@dataclass
class Command:
    """A /cmd_vel message as the robot received it; t is the sim time (robot's last /clock) relative to the origin."""

    t: float
    type: str
    linear: tuple[float, float, float]
    angular: tuple[float, float, float]
    after_sigint: bool


@dataclass
class RealResult:
    """What one probe run under real rclpy produced."""

    stdout: str
    stderr: str
    exit_code: int | None            # None: killed by the harness; negative: died from that signal
    commands: list[Command]
    origin_s: float | None           # the probe's #REF (absolute sim seconds)
    sigint_s: float | None           # sim time of the SIGINT, relative to the origin
    killed: bool = False
    wall_s: float = 0.0
    notes: list[str] = field(default_factory=list)


def _kill_group(pid: int, sig: int = signal.SIGKILL) -> None:
    try:
        os.killpg(pid, sig)
    except (ProcessLookupError, PermissionError):
        pass


class RealRos2:
    """A real rclpy robot on a domain id of its own; a context manager; run probes one at a time with `run_probe`."""

    def __init__(self, workdir: Path | None = None, speed: float = 1.0, startup_timeout_s: float = 30.0,
                 robot_node: Path = ROBOT_NODE, interfaces: Path | None = None) -> None:
        """`robot_node` stands for the robot (real_turtlesim2.py for turtlesim); `interfaces` is the install folder
        of an interface package built for real rclpy (build_turtlesim_interfaces.sh), put on every node's paths."""
        self._own_dir = workdir is None
        self.robot_node, self.interfaces = robot_node, interfaces
        self.dir = Path(workdir or tempfile.mkdtemp(prefix="rosgrade-realros2-"))
        self.speed = speed
        self.startup_timeout_s = startup_timeout_s
        self.robot: subprocess.Popen | None = None
        self.domain: DomainLock | None = None
        self.events: queue.Queue = queue.Queue()
        self._runs = 0
        self._lock = threading.Lock()

    def env(self) -> dict[str, str]:
        env = ros2_env(self.domain.domain_id, self.dir)
        if self.interfaces is not None:
            env["AMENT_PREFIX_PATH"] = f"{self.interfaces}:{env['AMENT_PREFIX_PATH']}"
            env["LD_LIBRARY_PATH"] = f"{self.interfaces / 'lib'}:{env['LD_LIBRARY_PATH']}"
            env["PYTHONPATH"] = ":".join(str(p) for p in sorted((self.interfaces / "lib").glob("python3*/site-packages")))
        return env

    def __enter__(self) -> RealRos2:
        reason = unavailable_reason()
        if reason:
            raise RealRos2Error(reason)
        try:
            self._start()
        except BaseException:
            self.close()
            raise
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _start(self) -> None:
        self.domain = DomainLock()
        for sub in ("ros_home", "log"):
            (self.dir / sub).mkdir(parents=True, exist_ok=True)
        self.robot = subprocess.Popen(
            [str(venv_python()), str(self.robot_node), "--speed", repr(self.speed)], env=self.env(), cwd=self.dir,
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=open(self.dir / "robot.err", "wb"),
            start_new_session=True, text=True, bufsize=1)
        threading.Thread(target=self._read_robot, daemon=True).start()
        event = self._next_event(lambda e: e["ev"] in ("ready", "error"), time.monotonic() + self.startup_timeout_s)
        if event is None or event["ev"] != "ready":
            raise RealRos2Error(f"the robot node did not start: {event}; see {self.dir / 'robot.err'}")

    def _read_robot(self) -> None:
        for line in self.robot.stdout:
            try:
                self.events.put(json.loads(line))
            except ValueError:
                self.events.put({"ev": "garbage", "line": line})
        self.events.put({"ev": "robot_exited"})

    def _next_event(self, accept, deadline: float) -> dict | None:
        while (left := deadline - time.monotonic()) > 0:
            try:
                event = self.events.get(timeout=left)
            except queue.Empty:
                return None
            if accept(event) or event["ev"] == "robot_exited":
                return event
        return None

    def _tell(self, line: str) -> None:
        self.robot.stdin.write(line + "\n")
        self.robot.stdin.flush()

    def close(self) -> None:
        """Stop the robot (its process group), release the domain id, remove the directory if it is ours."""
        if self.robot is not None and self.robot.poll() is None:
            _kill_group(self.robot.pid, signal.SIGTERM)
            try:
                self.robot.wait(3)
            except subprocess.TimeoutExpired:
                _kill_group(self.robot.pid)
                self.robot.wait(5)
        if self.domain is not None:
            self.domain.close()
        if self._own_dir:
            shutil.rmtree(self.dir, ignore_errors=True)

    def run_probe(self, probe: Path, args: tuple[str, ...] = (), *, shutdown_at: float | None = None,
                  duration: float = 4.0, wall_timeout_s: float | None = None) -> RealResult:
        """Run one probe to its end: SIGINT at `shutdown_at`, SIGKILL at `duration` sim seconds after its origin."""
        with self._lock:
            return self._run_probe(Path(probe), tuple(args), shutdown_at, duration, wall_timeout_s)

    def _run_probe(self, probe: Path, args: tuple[str, ...], shutdown_at: float | None, duration: float,
                   wall_timeout_s: float | None) -> RealResult:
        if self.robot is None or self.robot.poll() is not None:
            raise RealRos2Error("the robot node is not running")
        self._runs += 1
        run_id = f"r{self._runs}"
        stem = f"{run_id}.{probe.stem}"
        record = self.dir / f"{stem}.cmd.json"
        workdir = self.dir / run_id
        workdir.mkdir()
        # Wall budget: python and rclpy start-up, slow DDS discovery (up to ~2.7 s), the run, the shutdown sequence.
        budget = wall_timeout_s if wall_timeout_s is not None else duration / self.speed + 10.0
        wall0 = time.monotonic()
        with open(self.dir / f"{stem}.err", "wb") as err:
            proc = subprocess.Popen([str(venv_python()), str(probe.resolve()), *args], cwd=workdir, env=self.env(),
                                    stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=err,
                                    start_new_session=True)
        out_lines: list[str] = []
        origin: list[float] = []
        reader = threading.Thread(target=self._read_probe, args=(proc, out_lines, origin, shutdown_at, duration),
                                  daemon=True)
        result = RealResult("", "", None, [], None, None)
        try:
            self._tell(f"watch {run_id} {proc.pid} {record}")
            reader.start()
            deadline = wall0 + budget
            while True:
                code = proc.poll()
                if code is not None:
                    result.exit_code = code
                    break
                if time.monotonic() > deadline:
                    result.notes.append(f"wall budget of {budget:g} s exceeded; SIGKILL")
                    break
                try:
                    event = self.events.get(timeout=0.02)
                except queue.Empty:
                    continue
                if event["ev"] == "end" and event.get("watch") == run_id:
                    result.notes.append(f"still running {duration:g} sim s after its origin; SIGKILL")
                    break
                if event["ev"] in ("robot_exited", "error"):
                    result.notes.append(f"robot failed: {event}")
                    break
            if result.exit_code is None:
                result.killed = True
                _kill_group(proc.pid)
                proc.wait(5)
            # A publish from the except/finally block may still be in flight: give it 0.3 s wall.
            time.sleep(0.3)
            self._tell("unwatch")
            event = self._next_event(lambda e: e["ev"] == "unwatched", time.monotonic() + 5.0)
            if event is None or event["ev"] != "unwatched":
                result.notes.append(f"the robot did not write its record: {event}")
        finally:
            if proc.poll() is None:
                _kill_group(proc.pid)
                proc.wait(5)
            else:
                _kill_group(proc.pid)  # anything the probe left behind in its group
            reader.join(5)
        result.wall_s = time.monotonic() - wall0
        result.stdout = "".join(out_lines)
        result.stderr = (self.dir / f"{stem}.err").read_text(encoding="utf-8", errors="replace")
        result.origin_s = origin[0] if origin else None
        self._read_record(record, result)
        return result

    def _read_probe(self, proc: subprocess.Popen, out: list[str], origin: list[float], shutdown_at: float | None,
                    duration: float) -> None:
        """Collect the probe's stdout; at its '#REF' line, tell the robot when to send Ctrl+C and when time is up."""
        for raw in proc.stdout:
            line = raw.decode("utf-8", errors="replace")
            out.append(line)
            m = _REF.match(line)
            if m and not origin:
                origin.append(float(m.group(1)))
                shutdown = "-" if shutdown_at is None else str(round(shutdown_at * NS))
                self._tell(f"origin {round(origin[0] * NS)} {shutdown} {round(duration * NS)}")

    @staticmethod
    def _read_record(path: Path, result: RealResult) -> None:
        if not path.exists():
            return
        record = json.loads(path.read_text(encoding="utf-8"))
        origin_ns = record.get("origin_ns")
        sigint_ns = record.get("sigint_ns")
        base = origin_ns if origin_ns is not None else 0
        if sigint_ns is not None:
            result.sigint_s = (sigint_ns - base) / NS
        for c in record["commands"]:
            result.commands.append(Command((c["t_ns"] - base) / NS, c["type"], tuple(c["linear"]),
                                           tuple(c["angular"]), c["after_sigint"]))


def run_real(probe: Path, args: tuple[str, ...] = (), **kwargs) -> RealResult:
    """One probe beside a fresh robot (slower than sharing a `RealRos2`; for ad-hoc use)."""
    with RealRos2() as ros:
        return ros.run_probe(probe, args, **kwargs)


SIM_TIME_ARGS = ("--ros-args", "-p", "use_sim_time:=true")


if __name__ == "__main__":  # python real_ros2.py probe.py SHUTDOWN_AT [args...]: run one probe, show what it did
    res = run_real(Path(sys.argv[1]), (*sys.argv[3:], *SIM_TIME_ARGS), shutdown_at=float(sys.argv[2]))
    print(res.stdout, res.stderr, f"exit {res.exit_code} sigint_s {res.sigint_s} {res.notes}", sep="\n---\n")
    for c in res.commands:
        print(f"cmd t={c.t:.3f} {c.type} {c.linear} {c.angular} after_sigint={c.after_sigint}")
