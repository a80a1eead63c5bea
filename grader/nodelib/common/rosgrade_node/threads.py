"""Threads the student starts run under the lockstep scheduler, and thread waits (join, locks, Condition) in sim time.

A ``threading.Thread`` started from a managed thread becomes managed: it runs only while it holds the token, its
sleeps and rospy calls block in sim time, and ``join``, ``Lock``/``RLock`` acquisition, ``Condition.wait`` (so
``Event.wait``, ``queue.Queue.get``, ``threading.Timer``), ``queue.SimpleQueue`` (``ThreadPoolExecutor``) and the
interpreter's wait for non-daemon threads at exit block through the scheduler. A managed thread that waited in the C library instead would keep the token, and the
thread it waits for could never run. The recording then stays deterministic, and a waiting thread burns no wall
time. Known limit: a thread that spins in pure Python without any library call or wait is never pre-empted (only the
main thread has a CPU-time tick).
"""
from __future__ import annotations

import _thread
import queue
import threading

from . import runtime, timepatch

_original_start = threading.Thread.start
_original_join = threading.Thread.join
_original_is_alive = threading.Thread.is_alive
_original_wait = threading.Condition.wait
_original_shutdown = threading._shutdown
_allocate_lock = _thread.allocate_lock
_CRLock = threading.RLock
# Set while Thread.start itself waits for the new OS thread to come up: that wait is real, not the student's.
_starting = threading.local()


def _start(self: threading.Thread) -> None:
    sched = runtime.scheduler
    if (sched is None or getattr(self, "rosgrade_managed", False) or self._started.is_set()
            or not self._initialized or not sched.holds_token()):
        _starting.active = True
        try:
            _original_start(self)
        finally:
            _starting.active = False
        return
    waiter = sched.adopt(self.name, self.daemon)
    body = self.run
    self.run = lambda: sched.run_managed(waiter, body)
    self.rosgrade_waiter = waiter
    _starting.active = True
    try:
        _original_start(self)
    finally:
        _starting.active = False
    sched.register(waiter, self.ident)


def _join(self: threading.Thread, timeout=None) -> None:
    waiter = getattr(self, "rosgrade_waiter", None)
    sched = runtime.scheduler
    if waiter is None or sched is None or not sched.holds_token() or self is threading.current_thread():
        _original_join(self, timeout)
        return
    deadline = None if timeout is None else sched.world_ns + timepatch.seconds_to_ns(max(timeout, 0))
    while not waiter.finished and (deadline is None or sched.world_ns < deadline):
        sched.block(deadline_ns=deadline, ready=lambda: waiter.finished)
    if waiter.finished:
        _original_join(self)  # the OS thread ends right after handing the token on


def _is_alive(self: threading.Thread) -> bool:
    waiter = getattr(self, "rosgrade_waiter", None)
    if waiter is not None and waiter.finished:
        return False
    return _original_is_alive(self)


def _wait(self: threading.Condition, timeout=None) -> bool:
    sched = runtime.scheduler
    if sched is None or getattr(_starting, "active", False) or not sched.holds_token():
        return _original_wait(self, timeout)
    if not self._is_owned():
        raise RuntimeError("cannot wait on un-acquired lock")
    waiter = _thread.allocate_lock()
    waiter.acquire()
    self._waiters.append(waiter)
    saved = self._release_save()
    notified = False
    try:
        deadline = None if timeout is None else sched.world_ns + timepatch.seconds_to_ns(max(timeout, 0))
        while waiter.locked() and (deadline is None or sched.world_ns < deadline):
            sched.block(deadline_ns=deadline, ready=lambda: not waiter.locked())
        notified = not waiter.locked()
        return notified
    finally:
        self._acquire_restore(saved)
        if not notified:
            try:
                self._waiters.remove(waiter)
            except ValueError:
                pass


def _acquire(lock, free, blocking: bool, timeout: float) -> bool:
    """Acquire ``lock``: at once if free; in a managed thread, otherwise wait through the scheduler until ``free()``."""
    if lock.acquire(False):
        return True
    if not blocking:
        return False
    sched = runtime.scheduler
    if sched is None or not sched.holds_token():
        return lock.acquire(True, timeout)
    deadline = None if timeout < 0 else sched.world_ns + timepatch.seconds_to_ns(timeout)
    while True:
        sched.block(deadline_ns=deadline, ready=free)
        if lock.acquire(False):
            return True
        if deadline is not None and sched.world_ns >= deadline:
            return False


class _Lock:
    """threading.Lock whose blocking acquire waits through the scheduler in a managed thread."""

    __slots__ = ("_lock",)

    def __init__(self) -> None:
        self._lock = _allocate_lock()

    def acquire(self, blocking: bool = True, timeout: float = -1) -> bool:
        return _acquire(self._lock, self._free, blocking, timeout)

    def _free(self) -> bool:
        return not self._lock.locked()

    __enter__ = acquire

    def __exit__(self, *exc) -> None:
        self._lock.release()

    def release(self) -> None:
        self._lock.release()

    def locked(self) -> bool:
        return self._lock.locked()

    def _at_fork_reinit(self) -> None:
        self._lock._at_fork_reinit()

    def __repr__(self) -> str:
        return repr(self._lock)


class _RLock:
    """threading.RLock whose blocking acquire waits through the scheduler in a managed thread."""

    __slots__ = ("_lock",)

    def __init__(self) -> None:
        self._lock = _CRLock()

    def acquire(self, blocking: bool = True, timeout: float = -1) -> bool:
        return _acquire(self._lock, self._free, blocking, timeout)

    def _free(self) -> bool:
        # Only the token holder runs, so probing by acquiring and releasing races with no managed thread.
        if self._lock.acquire(False):
            self._lock.release()
            return True
        return False

    __enter__ = acquire

    def __exit__(self, *exc) -> None:
        self._lock.release()

    def release(self) -> None:
        self._lock.release()

    # What threading.Condition uses when its lock is an RLock.
    def _is_owned(self) -> bool:
        return self._lock._is_owned()

    def _release_save(self):
        return self._lock._release_save()

    def _acquire_restore(self, state) -> None:
        sched = runtime.scheduler
        if sched is not None and sched.holds_token():
            while not self._free():
                sched.block(ready=self._free)
        self._lock._acquire_restore(state)

    def _at_fork_reinit(self) -> None:
        self._lock._at_fork_reinit()

    def __repr__(self) -> str:
        return repr(self._lock)


def _shutdown() -> None:
    """Interpreter exit waits for the student's non-daemon threads: in sim time, through the scheduler."""
    sched = runtime.scheduler
    if sched is not None and sched.in_main_thread() and sched.holds_token():
        def all_done() -> bool:
            return all(w.finished or w.daemon for w in sched.adopted)

        while not all_done():
            sched.block(ready=all_done)
    _original_shutdown()


def install() -> None:
    threading.Thread.start = _start
    threading.Thread.join = _join
    threading.Thread.is_alive = _is_alive
    threading.Condition.wait = _wait
    threading.Lock = _Lock
    threading.RLock = _RLock
    # The C SimpleQueue's get() blocks in C (ThreadPoolExecutor's workers wait on one); the stdlib's pure-Python
    # version waits on a threading semaphore, which the scheduler handles.
    queue.SimpleQueue = queue._PySimpleQueue
    threading._shutdown = _shutdown
