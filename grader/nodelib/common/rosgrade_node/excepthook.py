"""EXCEPTION frames for uncaught exceptions (and for the ones rospy reports: callbacks, hooks), student frames only."""
from __future__ import annotations

import os
import sys
import threading
# Imported at start-up, not when first needed: CPython exits with 1 instead of by SIGINT when the excepthook of an
# uncaught KeyboardInterrupt (or an atexit hook) imports a module, and a node's Ctrl+C exit must stay as on ROS.
import traceback

import rosgrade_channel as ch

from . import runtime
from .scheduler import NODELIB_DIR  # none of its frames are the student's


def _is_student_frame(filename: str) -> bool:
    return not (filename.startswith(NODELIB_DIR) or filename.startswith("<frozen")
                or os.path.basename(filename) == "runpy.py")


def type_name(exc_type: type) -> str:
    """``ValueError`` for builtins, ``rospy.exceptions.ROSInterruptException`` otherwise."""
    module = exc_type.__module__
    return exc_type.__qualname__ if module == "builtins" else f"{module}.{exc_type.__qualname__}"


def report(exc_type: type, exc: BaseException | None, tb, where: str = "uncaught") -> None:
    """Send one EXCEPTION frame describing ``exc`` (no printing: the caller prints the traceback).

    ``where`` is "uncaught" (it ended a thread) or what rospy caught it in ("callback", "shutdown hook").
    """
    if runtime.link is None:
        return
    frames = [{"file": f.filename[:ch.MAX_PATH_CHARS], "line": f.lineno, "function": f.name[:ch.MAX_LABEL_CHARS],
               "text": (f.line or "")[:ch.MAX_MESSAGE_CHARS]}
              for f in traceback.extract_tb(tb) if _is_student_frame(f.filename)]
    runtime.link.send_json(ch.EXCEPTION, {
        "type": type_name(exc_type)[:ch.MAX_LABEL_CHARS],
        "message": str(exc)[:ch.MAX_MESSAGE_CHARS] if exc is not None else "",
        "frames": frames[-ch.MAX_TRACEBACK_FRAMES:],
        "where": where,
    })


def report_current(where: str) -> None:
    """Report the exception being handled right now, which rospy caught in ``where``."""
    report(*sys.exc_info(), where=where)


def _excepthook(exc_type, exc, tb) -> None:
    report(exc_type, exc, tb)
    sys.__excepthook__(exc_type, exc, tb)


def _thread_excepthook(args) -> None:
    if args.exc_type is not SystemExit:
        report(args.exc_type, args.exc_value, args.exc_traceback)
    threading.__excepthook__(args)


def install() -> None:
    sys.excepthook = _excepthook
    threading.excepthook = _thread_excepthook
