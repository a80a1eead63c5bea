"""Starts the node runtime inside the student's process: HELLO/START, streams, time patches, hooks, signals."""
from __future__ import annotations

import atexit
import os
import random
import signal
import sys

import rosgrade_channel as ch
import rosgrade_params
import rosgrade_qos

from . import cpus, excepthook, pids, realtime, runtime, streams, threads, timepatch
from .link import Link
from .scheduler import Scheduler

# CPU time between checks for a pure-Python busy wait in the main thread (see Scheduler.on_cpu_tick): one clock
# period, so such a wait costs about as much wall time as it would at a real-time factor of 1.
_CPU_TICK_S = 0.01
RANDOM_SEED = 0  # what the global `random` generator starts from in every node


class BootstrapError(Exception):
    """ROSGRADE_CHANNEL is malformed or START is unusable."""


def start(channel: str) -> None:
    """Connect to the grader named by ``channel`` ("<read_fd>,<write_fd>") and install the runtime."""
    try:
        read_fd, write_fd = (int(part) for part in channel.split(","))
    except ValueError:
        raise BootstrapError(f"ROSGRADE_CHANNEL must be '<read_fd>,<write_fd>', got {channel!r}") from None
    for fd in (read_fd, write_fd):
        os.set_inheritable(fd, False)   # a subprocess the student starts must not talk on our channel
    link = Link(read_fd, write_fd)
    link.send_json(ch.HELLO, {"protocol": ch.PROTOCOL, "pid": os.getpid(), "argv": list(sys.argv)})
    start_msg = link.read_json(ch.START)
    t_ns, wall_epoch = start_msg.get("t_ns"), start_msg.get("wall_epoch")
    params = start_msg.get("params") or {}
    if not isinstance(t_ns, int) or not isinstance(wall_epoch, (int, float)) or not isinstance(params, dict):
        raise BootstrapError(f"START needs integer t_ns, numeric wall_epoch and object params: {start_msg!r}")

    runtime.link = link
    runtime.scheduler = Scheduler(link, t_ns)
    runtime.params = params
    runtime.param_tree = runtime.scheduler.param_tree
    try:
        for name, value in params.items():
            rosgrade_params.set_value(runtime.param_tree, "/" + name.lstrip("/"), value)
    except TypeError as exc:
        raise BootstrapError(f"START params cannot make a parameter tree: {exc}") from None
    runtime.wall_epoch_ns = round(wall_epoch * 1e9)
    runtime.start_ns = t_ns
    runtime.ros_namespace = str(start_msg.get("ros_namespace") or "")
    runtime.world_topics = [tuple(pair) for pair in start_msg.get("world_topics") or ()
                            if isinstance(pair, list) and len(pair) == 2 and all(isinstance(x, str) for x in pair)]
    runtime.world_qos = _world_qos(start_msg.get("world_qos") or {})
    if runtime.ros_namespace:
        os.environ["ROS_NAMESPACE"] = runtime.ros_namespace
    if start_msg.get("interfaces"):  # the submission's own .msg/.srv/.action types, before its imports run
        import rosgrade_interfaces  # noqa: PLC0415 - the client library's own (its root is first on the path)
        rosgrade_interfaces.install(start_msg["interfaces"])

    sys.stdout = streams.make_stream(link, 1, 1, "strict")
    sys.stderr = streams.make_stream(link, 2, 2, "backslashreplace")
    timepatch.install()
    pids.install()  # after HELLO, which gives the grader the real pid
    cpus.install()  # after pids: the node's own pid is the one it sees
    threads.install()
    realtime.install()
    excepthook.install()
    # Python seeds `random` from os.urandom: a node that draws a number (the number game's secret) would record
    # something else on every run. A fixed seed makes its draws, and so its recording, the same every run.
    random.seed(RANDOM_SEED)
    atexit.register(_flush)

    sched = runtime.scheduler
    # Ctrl+C before init_node is Python's KeyboardInterrupt, delivered at a point where the main thread may run.
    signal.signal(signal.SIGINT, lambda signum, frame: sched.request_interrupt(f"signal-{signum}", frame))
    signal.signal(signal.SIGVTALRM, lambda signum, frame: sched.on_cpu_tick(frame))
    signal.setitimer(signal.ITIMER_VIRTUAL, _CPU_TICK_S, _CPU_TICK_S)


def _world_qos(obj) -> dict[str, tuple[str, str]]:
    """START's world_qos (topic -> [reliability, durability]), checked: a bad one is a BootstrapError."""
    try:
        return {str(topic): rosgrade_qos.check(*pair) for topic, pair in dict(obj).items()}
    except (TypeError, ValueError) as exc:
        raise BootstrapError(f"START world_qos must map topics to [reliability, durability]: {exc}") from None


def _flush() -> None:
    """Registered first, so it runs last at exit: stop the CPU timer, flush the streams and, in a batch of moments,
    tell the grader the moment the node ends at."""
    signal.setitimer(signal.ITIMER_VIRTUAL, 0, 0)
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    runtime.link.send_pending_moment()
