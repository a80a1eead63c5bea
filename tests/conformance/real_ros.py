"""Run a probe node under Debian's real ROS 1 (rospy + rosmaster) against a paced sim-time stand-in for Gazebo.

`RealRos` starts a private rosmaster on a free loopback port (ROS_HOME/ROS_LOG_DIR in a temporary directory), sets
``/use_sim_time`` true and starts ``real_sim_node.py`` (/clock every 10 ms at 1x wall, /odom and /tf at 30 Hz from a
kinematic unicycle driven by /cmd_vel). `RealRos.run_probe` starts one probe with ``/usr/bin/python3 probe.py args``,
sends it SIGINT at a sim time relative to the first /clock tick it received, SIGKILLs it after a bounded time, and
returns what it printed, its exit code and the /cmd_vel messages the sim received. Everything is bounded in time
and every process is started in its own process group and killed on the way out.
"""
from __future__ import annotations

import json
import os
import queue
import shutil
import signal
import socket
import subprocess
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

REAL_PYTHON = "/usr/bin/python3"
SIM_NODE = Path(__file__).resolve().parent / "real_sim_node.py"
SIM_START_S = 1.0
NS = 1_000_000_000
NOT_INSTALLED = "Debian's real ROS 1 (python3-rospy, rosmaster) is not installed"


class RealRosError(Exception):
    """The real-ROS harness could not run (master or sim did not come up, or a probe could not be started)."""


_available: bool | None = None


def real_ros_available() -> bool:
    """True when /usr/bin/python3 can import rospy, rosgraph and rosmaster (Debian's ROS 1 packages)."""
    global _available
    if _available is None:
        try:
            proc = subprocess.run([REAL_PYTHON, "-c", "import rospy, rosgraph, rosmaster, tf, nav_msgs.msg, tf2_msgs.msg"],
                                  capture_output=True, timeout=30, env=_clean_env())
            _available = proc.returncode == 0
        except (OSError, subprocess.TimeoutExpired):
            _available = False
    return _available


@dataclass
class Command:
    """A /cmd_vel message as the sim received it; t is the absolute sim time (the last /clock value published)."""

    t: float
    linear: tuple[float, float, float]
    angular: tuple[float, float, float]
    callerid: str


@dataclass
class RealResult:
    """What one probe run under real ROS produced."""

    stdout: str
    stderr: str
    exit_code: int | None           # None: killed by the harness; negative: died from that signal
    commands: list[Command]
    first_clock_s: float | None      # absolute sim time of the probe's first /clock tick
    sigint_s: float | None           # sim time of the SIGINT, relative to first_clock_s
    killed: bool = False
    wall_s: float = 0.0
    notes: list[str] = field(default_factory=list)


def _clean_env() -> dict[str, str]:
    """The environment of a terminal on a ROS machine: no pyenv/venv leftovers that could shadow Debian's packages."""
    keep = ("PATH", "LANG", "LC_ALL", "TZ", "TERM", "HOME", "USER")
    env = {k: os.environ[k] for k in keep if k in os.environ}
    env.setdefault("LANG", "C.UTF-8")
    return env


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _kill_group(proc: subprocess.Popen, sig: int = signal.SIGKILL) -> None:
    try:
        os.killpg(proc.pid, sig)
    except (ProcessLookupError, PermissionError):
        pass


class RealRos:
    """A private rosmaster and sim; use as a context manager, run probes one after another with `run_probe`."""

    def __init__(self, workdir: Path | None = None, startup_timeout_s: float = 20.0) -> None:
        self._own_dir = workdir is None
        self.dir = Path(workdir or tempfile.mkdtemp(prefix="rosgrade-realros-"))
        self.startup_timeout_s = startup_timeout_s
        self.master: subprocess.Popen | None = None
        self.sim: subprocess.Popen | None = None
        self.events: queue.Queue = queue.Queue()
        self.port = 0
        self._runs = 0
        self._lock = threading.Lock()

    # -- lifetime ----------------------------------------------------------------------------------------------
    def env(self) -> dict[str, str]:
        env = _clean_env()
        env.update(ROS_MASTER_URI=f"http://127.0.0.1:{self.port}", ROS_HOSTNAME="127.0.0.1", ROS_IP="127.0.0.1",
                   ROS_HOME=str(self.dir / "ros_home"), ROS_LOG_DIR=str(self.dir / "log"), HOME=str(self.dir),
                   PYTHONUNBUFFERED="1", PYTHONDONTWRITEBYTECODE="1")
        return env

    def __enter__(self) -> RealRos:
        if not real_ros_available():
            raise RealRosError(NOT_INSTALLED)
        try:
            self._start()
        except BaseException:
            self.close()
            raise
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _start(self) -> None:
        (self.dir / "ros_home").mkdir(parents=True, exist_ok=True)
        (self.dir / "log").mkdir(parents=True, exist_ok=True)
        deadline = time.monotonic() + self.startup_timeout_s
        for _attempt in range(3):
            self.port = _free_port()
            self.master = subprocess.Popen(
                [REAL_PYTHON, "/usr/bin/rosmaster", "--core", "-p", str(self.port)], env=self.env(),
                stdout=open(self.dir / "master.out", "wb"), stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                start_new_session=True)
            if self._wait_master(deadline):
                break
            _kill_group(self.master)
            self.master.wait(5)
        else:
            raise RealRosError(f"rosmaster did not start; see {self.dir / 'master.out'}")
        self._master_call("setParam", "/use_sim_time", True)
        self.sim = subprocess.Popen(
            [REAL_PYTHON, str(SIM_NODE), str(SIM_START_S)], env=self.env(), cwd=self.dir,
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=open(self.dir / "sim.err", "wb"),
            start_new_session=True, text=True, bufsize=1)
        threading.Thread(target=self._read_sim, daemon=True).start()
        event = self._next_event(lambda e: e["ev"] in ("ready", "error"), deadline)
        if event is None or event["ev"] != "ready":
            raise RealRosError(f"the sim node did not start: {event}; see {self.dir / 'sim.err'}")

    def _wait_master(self, deadline: float) -> bool:
        while time.monotonic() < deadline:
            if self.master.poll() is not None:
                return False
            try:
                self._master_call("getPid")
                return True
            except (OSError, RealRosError):
                time.sleep(0.05)
        return False

    def _master_call(self, method: str, *args: object) -> object:
        import xmlrpc.client
        proxy = xmlrpc.client.ServerProxy(f"http://127.0.0.1:{self.port}/")
        code, msg, value = getattr(proxy, method)("/conformance_harness", *args)
        if code != 1:
            raise RealRosError(f"master {method} failed: {msg}")
        return value

    def _read_sim(self) -> None:
        for line in self.sim.stdout:
            try:
                self.events.put(json.loads(line))
            except ValueError:
                self.events.put({"ev": "garbage", "line": line})
        self.events.put({"ev": "sim_exited"})

    def _next_event(self, accept, deadline: float) -> dict | None:
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            try:
                event = self.events.get(timeout=left)
            except queue.Empty:
                return None
            if accept(event) or event["ev"] == "sim_exited":
                return event

    def close(self) -> None:
        """Stop the sim and the master (process groups), and remove the temporary directory if it is ours."""
        for proc in (self.sim, self.master):
            if proc is not None and proc.poll() is None:
                _kill_group(proc, signal.SIGTERM)
                try:
                    proc.wait(2)
                except subprocess.TimeoutExpired:
                    _kill_group(proc)
                    proc.wait(5)
        if self.sim is not None and self.sim.stdin:
            try:
                self.sim.stdin.close()
            except OSError:
                pass
        if self._own_dir:
            shutil.rmtree(self.dir, ignore_errors=True)

    # -- probes ------------------------------------------------------------------------------------------------
    def run_probe(self, probe: Path, args: tuple[str, ...] = (), *, shutdown_at: float | None = None,
                  duration: float = 4.0, ros_namespace: str | None = None, wall_timeout_s: float | None = None,
                  ) -> RealResult:
        """Run one probe to its end; SIGINT at `shutdown_at` and SIGKILL at `duration` sim seconds after its first clock.

        Probes are run one at a time (the sim attributes /cmd_vel messages to the probe being watched).
        """
        with self._lock:
            return self._run_probe(Path(probe), tuple(args), shutdown_at, duration, ros_namespace, wall_timeout_s)

    def _run_probe(self, probe, args, shutdown_at, duration, ros_namespace, wall_timeout_s) -> RealResult:
        if self.sim is None or self.sim.poll() is not None:
            raise RealRosError("the sim node is not running")
        self._runs += 1
        run_id = f"r{self._runs}"
        out_path = self.dir / f"{run_id}.{probe.stem}.out"
        err_path = self.dir / f"{run_id}.{probe.stem}.err"
        env = self.env()
        if ros_namespace:
            env["ROS_NAMESPACE"] = ros_namespace
        workdir = self.dir / run_id
        workdir.mkdir()
        wall0 = time.monotonic()
        # Wall budget: startup (imports, init_node) plus the run itself at 1x plus the shutdown sequence.
        wall_budget = wall_timeout_s if wall_timeout_s is not None else duration + 8.0
        with open(out_path, "wb") as out, open(err_path, "wb") as err:
            proc = subprocess.Popen([REAL_PYTHON, str(probe), *args], cwd=workdir, env=env, stdin=subprocess.DEVNULL,
                                    stdout=out, stderr=err, start_new_session=True)
        result = RealResult("", "", None, [], None, None)
        try:
            shutdown = "-" if shutdown_at is None else repr(float(shutdown_at))
            self.sim.stdin.write(f"watch {run_id} {proc.pid} {shutdown} {float(duration)!r}\n")
            self.sim.stdin.flush()
            events: list[dict] = []
            deadline = wall0 + wall_budget
            while True:
                code = proc.poll()
                if code is not None:
                    result.exit_code = code
                    break
                if time.monotonic() > deadline:
                    result.notes.append(f"wall budget of {wall_budget:g} s exceeded; SIGKILL")
                    break
                try:
                    event = self.events.get(timeout=0.02)
                except queue.Empty:
                    continue
                events.append(event)
                if event["ev"] == "end" and event.get("watch") == run_id:
                    result.notes.append(f"still running {duration:g} sim s after its first clock; SIGKILL")
                    break
                if event["ev"] in ("sim_exited", "error"):
                    result.notes.append(f"sim failed: {event}")
                    break
            if result.exit_code is None:
                result.killed = True
                _kill_group(proc)
                proc.wait(5)
            # Messages still in flight (a publish from a shutdown hook, the last loop iteration) get 0.3 s wall.
            time.sleep(0.3)
            self.sim.stdin.write("unwatch\n")
            self.sim.stdin.flush()
            while True:
                try:
                    events.append(self.events.get(timeout=0.05))
                except queue.Empty:
                    break
        finally:
            if proc.poll() is None:
                _kill_group(proc)
                proc.wait(5)
            else:
                _kill_group(proc)  # anything the probe left behind in its group
        result.wall_s = time.monotonic() - wall0
        origin = next((e["t_ns"] for e in events if e["ev"] == "first_clock" and e.get("watch") == run_id), None)
        result.first_clock_s = None if origin is None else origin / NS
        for e in events:
            if e.get("watch") != run_id:
                continue
            if e["ev"] == "sigint" and origin is not None:
                result.sigint_s = (e["t_ns"] - origin) / NS
            elif e["ev"] == "cmd":
                result.commands.append(Command(e["t_ns"] / NS, tuple(e["linear"]), tuple(e["angular"]), e["callerid"]))
        result.stdout = out_path.read_text(encoding="utf-8", errors="replace")
        result.stderr = err_path.read_text(encoding="utf-8", errors="replace")
        return result


def run_real(probe: Path, args: tuple[str, ...] = (), **kwargs) -> RealResult:
    """One probe in a fresh master and sim (slower than sharing a `RealRos`; for ad-hoc use)."""
    with RealRos() as ros:
        return ros.run_probe(probe, args, **kwargs)
