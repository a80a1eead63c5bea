"""Turn how a node process ended (exit code, signal, last exception, what it left running) into a status and a plain
explanation a student can act on."""
from __future__ import annotations

import re
import signal
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grader.runtime.node_link import NodeState
    from grader.runtime.process import NodeProcess
    from grader.runtime.spec import Limits

# What a node can import in the grader, for "X is not available" messages.
AVAILABLE = ("rospy, the standard ROS message packages, tf, tf2_ros, tf2_geometry_msgs, message_filters, roslib, rospkg, "
             "numpy and the Python standard library")

_SIGNAL_TEXT = {
    signal.SIGSEGV: "crashed with a segmentation fault (SIGSEGV): the Python process itself died, e.g. from a bad "
                    "ctypes call, a broken C extension or unbounded recursion after raising the recursion limit",
    signal.SIGABRT: "aborted (SIGABRT): the Python interpreter or a C library stopped the process",
    signal.SIGBUS: "crashed with a bus error (SIGBUS)",
    signal.SIGFPE: "crashed with a floating-point exception (SIGFPE)",
    signal.SIGILL: "crashed with an illegal instruction (SIGILL)",
    signal.SIGKILL: "was killed with SIGKILL, not by the grader (did it kill its own process group?)",
    signal.SIGTERM: "was terminated with SIGTERM, not by the grader (did it signal its own process group?)",
}


class OutputLimitExceeded(Exception):
    """The node printed more than its output limit; it is stopped."""


def _signal_name(sig: int) -> str:
    return signal.Signals(sig).name if sig in signal.Signals._value2member_map_ else str(sig)


def exit_status(code: int | None, limits: Limits | None = None) -> tuple[str, str]:
    """(status, message) for a process that ended with `code` (negative: killed by that signal)."""
    if code is None:
        return "timeout", "closed its channel but did not exit"
    if code >= 0:
        return "exited", f"exited with code {code}"
    sig = -code
    if sig == signal.SIGXCPU:
        extra = f" of {limits.cpu_s:g} s" if limits else ""
        return "killed_by_limit", f"exceeded its CPU-time limit{extra}"
    if sig == signal.SIGXFSZ:
        extra = f" of {limits.file_mb} MB" if limits else ""
        return "killed_by_limit", f"exceeded its file-size limit{extra} (it wrote a file that large)"
    if sig in _SIGNAL_TEXT:
        return "crashed", _SIGNAL_TEXT[sig]
    return "crashed", f"died from signal {_signal_name(sig)}"


def missing_module(exception: dict | None) -> str | None:
    """The top-level module a ModuleNotFoundError names, if that is how the node ended."""
    if not exception or exception.get("type") not in ("ModuleNotFoundError", "ImportError"):
        return None
    match = re.search(r"No module named '([^']+)'", str(exception.get("message", "")))
    return match.group(1).split(".")[0] if match else None


def refine(status: str, message: str, code: int | None, state: NodeState, process: NodeProcess | None,
           limits: Limits, findings: list[str] | None = None) -> tuple[str, str]:
    """Sharpen a verdict with what else was observed: the exception the node died of, the processes it left."""
    exception = state.exception or {}
    kind = str(exception.get("type", ""))
    text = str(exception.get("message", ""))
    if code is not None and code < 0 and status in ("exited", "crashed", "killed_by_limit") \
            and message == exit_status(code)[1]:
        status, message = exit_status(code, limits)
    if status in ("exited", "crashed", "timeout", "protocol_violation") and process is not None \
            and process.hit_process_limit:
        return ("killed_by_limit", f"started {process.peak_tasks} processes and threads and could start no more, at "
                                   f"its limit of {limits.processes} (a fork bomb or runaway threads?); it was "
                                   "stopped and everything it started killed")
    if status in ("exited", "crashed") and kind == "MemoryError":
        return "killed_by_limit", f"ran out of memory: the limit is {limits.memory_mb} MB (MemoryError)"
    if status in ("exited", "crashed", "timeout", "protocol_violation") and kind == "BlockingIOError" \
            and "Resource temporarily unavailable" in text:
        return ("killed_by_limit", f"could not start another process or thread: the limit is {limits.processes} "
                                   "(a fork bomb or runaway threads?)")
    if status == "timeout" and "did not yield" in message:
        message += "; a thread of its own that never ends keeps a node from finishing in the same way"
    if status == "exited":
        module = missing_module(exception)
        if module:
            note = (f"{module} is not available in the grader: {kind}: {text}. The grader provides {AVAILABLE}; "
                    f"remove the import of {module} or ask your instructor whether it may be used.")
            if findings is not None and note not in findings:
                findings.append(note)
            return status, f"{message}: {module} is not available in the grader ({kind}: {text})"
        if kind == "RecursionError":
            return status, f"{message} after unbounded recursion (RecursionError: {text})"
        if kind:
            return status, f"{message} after an uncaught {kind}: {text}"
    return status, message
