"""The lockstep scheduler: one token shared by every thread that runs student code, sim-time waits, WAIT/batch exchange.

Managed threads are the main thread, one callback thread per subscribed topic, rospy.Timer threads and the threads the
student starts from a managed thread (see threads.py). Exactly one of
them holds the token and runs; a blocking library call (``block``) registers a wake condition and passes the token on.
When no thread can run, the thread that blocked last sends ``WAIT {wake_ns}`` and applies the grader's batch (or, in a
batch of moments, moves on itself to the next later moment or wake-up of its own while nothing it did could change the
world). After a batch or
moment the order is fixed: topic threads that received messages (in delivery order), then threads whose wake
condition holds, by (deadline, time of blocking), then the main thread if only a shutdown request woke it. Student
code therefore interleaves as a function of the grader's batches alone.
"""
from __future__ import annotations

import _thread
import itertools
import os
import sys
import sysconfig
import threading
from collections import deque
from collections.abc import Callable

import rosgrade_channel as ch
import rosgrade_params

from .link import Link, Moment

# Code in these directories is library code: a CPU-time tick that lands in it never yields (see on_cpu_tick).
# nodelib/ (common/ and every client library's root: rospy's and rclpy's frames are library frames too).
NODELIB_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))) + os.sep
_LIBRARY_DIRS = tuple(
    {NODELIB_DIR}
    | {os.path.join(p, "") for key in ("stdlib", "platstdlib", "purelib", "platlib")
       if (p := sysconfig.get_paths().get(key))})


class SchedulerError(Exception):
    """The grader broke the lockstep contract (time moved backwards)."""


def _raise_keyboard_interrupt(reason: str) -> None:
    """What a Ctrl+C does to a process that has not handed signals to rospy."""
    raise KeyboardInterrupt


class _Waiter:
    """One managed thread's scheduling state."""

    __slots__ = ("name", "turn", "deadline_ns", "ready", "seq", "ident", "finished", "daemon", "busy")

    def __init__(self, name: str, daemon: bool = True) -> None:
        self.name = name
        self.daemon = daemon
        self.finished = False
        # Held except between the hand-over of the token to this thread and its taking it: a bare lock is a
        # semaphore of one, under half the cost of a threading.Event per hand-over, which a node pays every step.
        self.turn = _thread.allocate_lock()
        self.turn.acquire()
        self.deadline_ns: int | None = None
        self.ready: Callable[[], bool] | None = None
        self.seq = 0
        self.ident: int | None = None
        self.busy = False  # it gives up only the sim time its calls charged: still runnable (a busy loop)


class Scheduler:
    """Token passing, the sim clock as the node sees it, call charges, and the grader exchange."""

    def __init__(self, link: Link, t_ns: int) -> None:
        self.link = link
        self.world_ns = t_ns
        self.clock_ns = 0
        self.charge_ns = 0
        # Counts library calls and blocks; the CPU-time tick yields only when it has not moved.
        self.activity = 0
        self._tick_activity = -1
        # Set by init_node: before it no callback can run, so no busy wait can be waiting for one.
        self.node_initialized = False
        self.interrupt_pending: str | None = None
        self.on_interrupt: Callable[[str], None] = _raise_keyboard_interrupt
        self._seq = itertools.count()
        self._main = _Waiter("MainThread")
        self._main.ident = threading.get_ident()
        self._holder: _Waiter | None = self._main
        self._threads: dict[int, _Waiter] = {self._main.ident: self._main}
        self._blocked: dict[_Waiter, None] = {}
        self._runnable: deque[_Waiter] = deque()
        self._sinks: dict[int, tuple[Callable[..., _Waiter | None], bool]] = {}
        # Topic handle -> how many nodes it is connected to, as the grader last said (get_num_connections()).
        self.connections: dict[int, int] = {}
        # Topic handle -> the policies of incompatible peers discovered, not yet logged (rclpy's QoS event handlers).
        self.qos_events: dict[int, list[str]] = {}
        # The run's parameter server as this node sees it (bootstrap fills it from START; batches bring the changes
        # other nodes made, applied before any thread runs, so every thread reads the same tree at one world time).
        self.param_tree: dict = {}
        # Threads started outside the token (from a thread the scheduler does not manage) wait here.
        self._outside = threading.Condition()
        self.adopted: list[_Waiter] = []  # student threads, in start order
        # The later moments of the current batch not run yet, and how far the world ran ahead for them (None: no
        # batch of moments is being run).
        self._later: deque[Moment] = deque()
        self._until: int | None = None

    # -- queries ---------------------------------------------------------------------------------------------------
    def holds_token(self) -> bool:
        """True when the calling thread is the managed thread that may run now."""
        me = self._threads.get(threading.get_ident())
        return me is not None and me is self._holder

    def in_main_thread(self) -> bool:
        return threading.get_ident() == self._main.ident

    # -- non-blocking calls ----------------------------------------------------------------------------------------
    def charge(self) -> None:
        """Account one non-blocking library call; yield once the charge reaches a clock period (busy loops)."""
        if not self.holds_token():
            return
        self.activity += 1
        self.charge_ns += ch.CALL_QUANTUM_NS
        if self.charge_ns >= ch.CLOCK_PERIOD_NS:
            self._yield_busy()

    def on_cpu_tick(self, frame) -> None:
        """SIGVTALRM handler body: make a pure-Python busy wait in the main thread give up one clock period.

        Trade-off: a loop that makes no library call (``while self.odom is None: pass``) could otherwise never let
        the callback that ends it run. The timer counts CPU time, so *when* it fires depends on the machine; to keep
        that out of the recording for ordinary nodes it only acts after init_node, when the main thread holds the
        token, is executing student code (not library, stdlib or generated ``<...>`` code such as the message classes
        built at import) and has made no library call since the previous tick. A wait for
        a message then still ends at a deterministic sim time (each tick advances exactly one period until the
        message's batch); only long pure-Python computations see machine-dependent sim time.
        """
        if not self.node_initialized or not self.holds_token() or not self.in_main_thread():
            return
        if self.activity != self._tick_activity:
            self._tick_activity = self.activity
            return
        filename = frame.f_code.co_filename if frame is not None else "<frozen>"
        if filename.startswith(_LIBRARY_DIRS) or filename.startswith("<"):
            return
        self.charge_ns += ch.CLOCK_PERIOD_NS
        self._yield_busy()
        self._tick_activity = self.activity

    def _yield_busy(self) -> None:
        """Give up the charged sim time while staying runnable: the grader hears a busy WAIT (real rospy's own threads
        then wait for the GIL, which delays a publisher's connection)."""
        me = self._threads[threading.get_ident()]
        me.busy = True
        try:
            self.block(deadline_ns=self.world_ns + self.charge_ns)
        finally:
            me.busy = False

    # -- blocking ------------------------------------------------------------------------------------------------
    def block(self, deadline_ns: int | None = None, ready: Callable[[], bool] | None = None) -> None:
        """Give up the token until world time reaches ``deadline_ns`` or ``ready()`` holds.

        The main thread also wakes for a pending interrupt (SHUTDOWN frame or signal) and runs ``on_interrupt`` here,
        at its waiting point, holding the token; that may raise KeyboardInterrupt. Callers re-check their own
        condition in a loop.
        """
        me = self._threads.get(threading.get_ident())
        if me is None:
            self._block_outside(deadline_ns, ready)
            return
        self.activity += 1
        me.deadline_ns, me.ready = deadline_ns, ready
        if not self._is_ready(me):
            me.seq = next(self._seq)
            self._blocked[me] = None
            self._switch(me)
        me.deadline_ns = me.ready = None
        if me is self._main and self.interrupt_pending is not None:
            reason, self.interrupt_pending = self.interrupt_pending, None
            self.on_interrupt(reason)

    def sleep_ns(self, ns: int) -> None:
        """Sleep ``ns`` of world time, waking at the exact deadline (patched time.sleep); 0 only charges."""
        if ns <= 0:
            self.charge()
            return
        deadline = self.world_ns + ns
        while self.world_ns < deadline:
            self.block(deadline_ns=deadline)

    def request_interrupt(self, reason: str, frame=None) -> None:
        """A Ctrl+C for the main thread (a signal handler's body): run it now if the main thread is in student code,
        otherwise at the main thread's next waiting point."""
        filename = frame.f_code.co_filename if frame is not None else "<frozen>"
        if self.holds_token() and self.in_main_thread() and not filename.startswith(_LIBRARY_DIRS) \
                and not filename.startswith("<frozen"):
            self.on_interrupt(reason)
        else:
            self.interrupt_pending = reason

    # -- threads ---------------------------------------------------------------------------------------------------
    def spawn(self, name: str, target: Callable[[], None], ready: Callable[[], bool] | None = None) -> _Waiter:
        """Start a managed daemon thread. It first runs when handed the token: in FIFO order after the current
        holder blocks, or (with ``ready``) once ``ready()`` holds."""
        waiter = _Waiter(name)
        thread = threading.Thread(target=lambda: self.run_managed(waiter, target), name=name, daemon=True)
        thread.rosgrade_managed = True  # threads.py leaves it alone
        waiter.seq = next(self._seq)
        if ready is None:
            self._runnable.append(waiter)
        else:
            waiter.ready = ready
            self._blocked[waiter] = None
        thread.start()
        waiter.ident = thread.ident
        self._threads[thread.ident] = waiter
        return waiter

    def adopt(self, name: str, daemon: bool) -> _Waiter:
        """A student thread about to start: it first runs, in FIFO order, once the current holder blocks."""
        waiter = _Waiter(name, daemon)
        waiter.seq = next(self._seq)
        self._runnable.append(waiter)
        self.adopted.append(waiter)
        return waiter

    def register(self, waiter: _Waiter, ident: int) -> None:
        """The adopted thread has started (before it can hold the token)."""
        waiter.ident = ident
        self._threads[ident] = waiter

    def run_managed(self, waiter: _Waiter, target: Callable[[], None]) -> None:
        """A managed thread's body: wait for the token, run target, report what escaped it, hand the token on."""
        waiter.turn.acquire()
        try:
            target()
        except SystemExit:
            pass
        except BaseException:
            threading.excepthook(threading.ExceptHookArgs((*sys.exc_info(), threading.current_thread())))
        finally:
            self._exit(waiter)

    def add_sink(self, ident: int, sink: Callable[..., _Waiter | None], sources: bool = False) -> None:
        """Route deliveries (in BATCH frames) for handle ``ident``; the sink returns the thread that will consume the
        message. With ``sources`` it is also given who published it: ``(callerid, latched)``, or None for the world."""
        self._sinks[ident] = (sink, sources)

    def remove_sink(self, ident: int) -> None:
        self._sinks.pop(ident, None)

    # -- internals -------------------------------------------------------------------------------------------------
    def _is_ready(self, w: _Waiter) -> bool:
        return ((w.deadline_ns is not None and self.world_ns >= w.deadline_ns)
                or (w.ready is not None and w.ready())
                or (w is self._main and self.interrupt_pending is not None))

    def _order(self, w: _Waiter) -> tuple:
        woken = (w.deadline_ns is not None and self.world_ns >= w.deadline_ns) or (w.ready is not None and w.ready())
        if not woken:  # only the pending interrupt woke the main thread: it goes last
            return (1, 0, w.seq)
        return (0, w.deadline_ns if w.deadline_ns is not None else self.world_ns, w.seq)

    def _pick(self) -> _Waiter | None:
        if not self._runnable:
            self._runnable.extend(sorted((w for w in self._blocked if self._is_ready(w)), key=self._order))
        if not self._runnable:
            return None
        w = self._runnable.popleft()
        self._blocked.pop(w, None)
        return w

    def _switch(self, me: _Waiter | None) -> None:
        """Hand the token to the next runnable thread (exchanging with the grader when there is none) and, unless
        ``me`` is exiting, wait until it comes back."""
        nxt = self._pick()
        while nxt is None:
            self._exchange()
            nxt = self._pick()
        self._holder = nxt
        if nxt is me:
            return
        nxt.turn.release()
        if me is not None:
            me.turn.acquire()

    def _exit(self, w: _Waiter) -> None:
        w.finished = True
        self._threads.pop(w.ident, None)
        self._blocked.pop(w, None)
        self._switch(None)

    def _exchange(self) -> None:
        """Send WAIT with the earliest deadline, apply the grader's batch and queue the threads it wakes.

        A batch may carry later moments (times at which it only receives messages) and a horizon the world has run
        ahead to. The node runs those moments, and its own wake-ups up to the horizon, on its own, as long as
        nothing it did can change the world or its next batches: only log lines, printed text and the messages the
        batch calls inert (see Link.send). Then the grader, which ran the world ahead speculatively, has nothing to
        undo. Each moment's time goes to the grader (MOMENT) before the first frame sent there; at the first moment
        where the node acts otherwise it stops there and skips the rest: the grader takes the world back to it."""
        deadlines = [w.deadline_ns for w in self._blocked if w.deadline_ns is not None]
        wake = min(deadlines) if deadlines else None
        if self._until is not None:
            if not self.link.acted and self.interrupt_pending is None:
                later = self._later[0] if self._later else None
                if wake is not None and wake <= self._until and (later is None or wake < later.t_ns):
                    # a wake-up of its own: the grader's lockstep would stop here with nothing to deliver
                    self.link.pending_moment = wake
                    self._apply(wake, (wake // ch.CLOCK_PERIOD_NS) * ch.CLOCK_PERIOD_NS, [], None)
                    return
                if later is not None:
                    self._later.popleft()
                    self.link.pending_moment = later.t_ns
                    self._apply(later.t_ns, later.clock_ns, later.deliveries, None)
                    return
            self._later.clear()
            self._until = None
        self.link.send(ch.encode_wait(wake, any(w.busy for w in self._blocked)))
        batch = self.link.read_batch()
        self.connections.update(batch.connections)
        for ident, policy in batch.qos_events:
            self.qos_events.setdefault(ident, []).append(policy)
        rosgrade_params.apply(self.param_tree, batch.params)
        if batch.until_ns is not None:
            self._later.extend(batch.moments)
            self._until = batch.until_ns
            self.link.begin_moments(batch.t_ns, batch.inert)
        self._apply(batch.t_ns, batch.clock_ns, batch.deliveries, batch.shutdown)

    def _apply(self, t_ns: int, clock_ns: int, deliveries: list[tuple], shutdown: str | None) -> None:
        """Move to world time ``t_ns``, hand the deliveries to their topics and queue the threads they wake."""
        if t_ns < self.world_ns:
            raise SchedulerError(f"grader moved world time backwards: {t_ns} < {self.world_ns}")
        if t_ns > self.world_ns:
            self.charge_ns = 0
        self.world_ns, self.clock_ns = t_ns, clock_ns
        woken: dict[_Waiter, None] = {}
        for ident, data, *source in deliveries:
            sink, sources = self._sinks.get(ident, (None, False))
            if sink is None:
                continue
            consumer = sink(data, source[0] if source else None) if sources else sink(data)
            if consumer is not None:
                woken[consumer] = None
        if shutdown is not None:
            self.interrupt_pending = shutdown
        for w in woken:
            if w in self._blocked and self._is_ready(w):
                del self._blocked[w]
                self._runnable.append(w)
        with self._outside:
            self._outside.notify_all()

    def _block_outside(self, deadline_ns: int | None, ready: Callable[[], bool] | None) -> None:
        """A thread the node did not create waits outside the token (not deterministic; documented limitation)."""
        with self._outside:
            self._outside.wait_for(lambda: (deadline_ns is not None and self.world_ns >= deadline_ns)
                                   or (ready is not None and ready()))
