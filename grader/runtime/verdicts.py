"""Turn how a node process ended (exit code, signal) into a status and a plain explanation."""
from __future__ import annotations

import signal


def exit_status(code: int | None) -> tuple[str, str]:
    """(status, message) for a process that ended with `code` (negative: killed by that signal)."""
    if code is None:
        return "timeout", "closed its channel but did not exit"
    if code >= 0:
        return "exited", f"exited with code {code}"
    sig = -code
    if sig == signal.SIGXCPU:
        return "killed_by_limit", "exceeded its CPU-time limit"
    if sig == signal.SIGXFSZ:
        return "killed_by_limit", "exceeded its file-size limit"
    name = signal.Signals(sig).name if sig in signal.Signals._value2member_map_ else str(sig)
    return "crashed", f"died from signal {name}"
