#!/usr/bin/env python3
"""Tries to reach the grader (its pid given, as getppid() gives it without a PID namespace): its environment, cwd
and stdout through /proc, ptrace; and the terminal."""
import ctypes
import os
import sys
import rospy
rospy.init_node("reacher")
parent = int(sys.argv[1])
libc = ctypes.CDLL(None, use_errno=True)


def attempt(what, action):
    try:
        print("REACHED", what, repr(action())[:60])
    except OSError as exc:
        print("blocked", what, type(exc).__name__)


def ptrace():
    if libc.ptrace(16, parent, 0, 0) != 0:  # PTRACE_ATTACH
        raise OSError(ctypes.get_errno(), "ptrace")
    libc.ptrace(17, parent, 0, 0)  # PTRACE_DETACH
    return "attached"


attempt("environ", lambda: open(f"/proc/{parent}/environ", "rb").read())
attempt("cwd", lambda: os.listdir(f"/proc/{parent}/cwd"))
attempt("stdout", lambda: open(f"/proc/{parent}/fd/1", "w").write("PWNED through /proc\n"))
attempt("tty", lambda: open("/dev/tty", "w").write("PWNED through /dev/tty\n"))
attempt("ptrace", ptrace)
os.write(1, b"own stdout only\n")
