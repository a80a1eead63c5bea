"""rclpy.executors: Single- and MultiThreadedExecutor on rosgrade's lockstep scheduler.

An executor waits (``scheduler.block``) until one of its nodes has work: a timer due (the wake time is the first
/clock tick at or after its next call on sim time, or the exact wall/steady time otherwise), a delivered message, a
service response or request, a triggered guard condition or task, the spin's future or timeout, or a context
shutdown. One wait gives a list of ready work in rclpy's order (tasks, the waitables of every node: action servers
and clients, then per node: timers, the /clock subscription, subscriptions, guard conditions, clients, services); each ``spin_once`` runs the next item, and waits
again only once the list is used up. A SingleThreadedExecutor runs callbacks in the spinning thread, so a
callback that blocks starves everything else, the node's clock included. ``spin()`` applies a new /clock when it
looks at a node instead of treating it as an item of its own (the same times, without a wake-up per tick);
``spin_once`` counts it as work.
"""
from __future__ import annotations

import inspect
import os
import warnings
from collections import deque

from . import _runtime
from .clock import sleep_epoch
from .task import Task
from .utilities import get_default_context, timeout_sec_to_nsec


class TimeoutException(Exception):
    """Signal that a timeout occurred."""


class ShutdownException(Exception):
    """Signal that executor was shut down."""


class ExternalShutdownException(Exception):
    """Context has been shutdown."""


class ConditionReachedException(Exception):
    """Future has been completed."""


async def await_or_execute(callback, *args):
    """Await a callback if it is a coroutine function, else call it."""
    if inspect.iscoroutinefunction(callback):
        return await callback(*args)
    return callback(*args)


class TimeoutObject:
    def __init__(self, timeout: float) -> None:
        self.timeout = timeout


def _never() -> bool:
    return False


class Executor:
    """The base class: node bookkeeping, waiting for work and running one item of it."""

    def __init__(self, *, context=None) -> None:
        self._context = get_default_context() if context is None else context
        self._nodes: list = []
        self._tasks: list[tuple[Task, object, object]] = []
        self._is_shutdown = False
        self._guard_triggered = False
        self._work: deque = deque()
        self._context.on_shutdown(self.wake)

    @property
    def context(self):
        return self._context

    def create_task(self, callback, *args, **kwargs) -> Task:
        task = Task(callback, args, kwargs, executor=self)
        self._tasks.append((task, None, None))
        self._guard_triggered = True
        return task

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        self._is_shutdown = True
        self._nodes = []
        self._work.clear()
        return True

    def add_node(self, node) -> bool:
        if node in self._nodes:
            return False
        self._nodes.append(node)
        node.executor = self
        self._guard_triggered = True
        return True

    def remove_node(self, node) -> None:
        if node in self._nodes:
            self._nodes.remove(node)
            self._guard_triggered = True

    def wake(self) -> None:
        self._guard_triggered = True

    def get_nodes(self) -> list:
        return list(self._nodes)

    def spin(self) -> None:
        while self._context.ok() and not self._is_shutdown:
            self._spin_once_impl(None, _never, clock_is_work=False)

    def spin_until_future_complete(self, future, timeout_sec: float | None = None) -> None:
        future.add_done_callback(lambda _: self.wake())
        if timeout_sec is None or timeout_sec < 0:
            while self._context.ok() and not future.done() and not self._is_shutdown:
                self._spin_once_impl(None, future.done, clock_is_work=False)
            return
        end = _runtime.steady_ns() + int(timeout_sec * 1e9)
        while self._context.ok() and not future.done() and not self._is_shutdown:
            left = end - _runtime.steady_ns()
            if left <= 0:
                return
            self._spin_once_impl(left / 1e9, future.done, clock_is_work=False)

    def spin_once(self, timeout_sec: float | None = None) -> None:
        self._spin_once_impl(timeout_sec, _never, clock_is_work=True)

    def spin_once_until_future_complete(self, future, timeout_sec: float | None = None) -> None:
        future.add_done_callback(lambda _: self.wake())
        self._spin_once_impl(timeout_sec, future.done, clock_is_work=True)

    def _spin_once_impl(self, timeout_sec, condition, clock_is_work: bool) -> None:
        raise NotImplementedError()

    def __enter__(self) -> Executor:
        return self

    def __exit__(self, *exc) -> None:
        self.shutdown()

    # -- waiting ----------------------------------------------------------------------------------------------------
    def can_execute(self, entity) -> bool:
        group = getattr(entity, "callback_group", None)
        return group is None or group.can_execute(entity)

    def _ready_work(self, clock_is_work: bool) -> list:
        """What is ready now, in rclpy's order (one wait set's worth)."""
        # a task already queued for a worker (MultiThreadedExecutor) is not work again
        work: list = [(task, "task", node) for task, _, node in self._tasks
                      if not task.executing() and not task.done() and (node is None or node in self._nodes)
                      and self.can_execute(task)]
        self._tasks = [entry for entry in self._tasks if not entry[0].done()]
        self._guard_triggered = False
        if not clock_is_work:
            for node in self._nodes:
                node._time_source.apply_clock()
        for node in list(self._nodes):
            work += [(w, "waitable", node) for w in node._waitables if self.can_execute(w) and w.is_ready(None)]
        for node in list(self._nodes):
            source = node._time_source
            work += [(t, "timer", node) for t in node._timers if self.can_execute(t) and t.is_ready()]
            # a MultiThreadedExecutor's queued /clock job, not yet run by a worker, is not work again
            if clock_is_work and source.clock_pending() and self.can_execute(source):
                work.append((source, "clock", node))
            work += [(s, "sub", node) for s in node._subscriptions if s.has_message() and self.can_execute(s)]
            work += [(g, "guard", node) for g in node._guards if g._triggered and self.can_execute(g)]
            work += [(c, "client", node) for c in node._clients if c.has_response() and self.can_execute(c)]
            work += [(s, "service", node) for s in node._services if s.has_request() and self.can_execute(s)]
        return work

    def _anything_ready(self, condition) -> bool:
        if self._is_shutdown or self._guard_triggered or not self._context.ok() or condition():
            return True
        # only what may run now: work of a group busy with another callback waits for a worker to finish (which
        # triggers the executor's guard), else the wait would end at once and spin without yielding
        for node in self._nodes:
            if any(s.has_message() and self.can_execute(s) for s in node._subscriptions) \
                    or any(g._triggered and self.can_execute(g) for g in node._guards) \
                    or any(c.has_response() and self.can_execute(c) for c in node._clients) \
                    or any(s.has_request() and self.can_execute(s) for s in node._services) \
                    or any(w.is_ready(None) and self.can_execute(w) for w in node._waitables):
                return True
        return False

    def _wake_ns(self, deadline_ns: int | None, clock_is_work: bool) -> int | None:
        wakes = [] if deadline_ns is None else [deadline_ns]
        for node in self._nodes:
            wakes += [w for t in node._timers if self.can_execute(t) and (w := t.wake_world_ns()) is not None]
            source = node._time_source
            if clock_is_work and source.ros_time_is_active:
                wakes.append(_runtime.clock_wake_ns(0))
            elif not clock_is_work and (target := source.first_sleep_target()) is not None:
                wakes.append(_runtime.clock_wake_ns(target))  # spin() applies the /clock a sleeper waits for
        return min(wakes) if wakes else None

    def wait_for_ready_callbacks(self, timeout_sec=None, nodes=None, condition=_never, clock_is_work: bool = True):
        """The next ready item ``(entity, kind, node)``, waiting for one if none is left from the last wait.

        Raises TimeoutException, ShutdownException, ExternalShutdownException (context shut down while waiting)
        or ConditionReachedException, as rclpy's generator does."""
        while self._work:
            item = self._work.popleft()
            if self._still_ready(item):
                return item
        timeout = timeout_sec.timeout if isinstance(timeout_sec, TimeoutObject) else timeout_sec
        timeout_ns = timeout_sec_to_nsec(timeout)
        sched = _runtime.scheduler()
        deadline = sched.world_ns + timeout_ns if timeout_ns > 0 else None
        while not self._is_shutdown and not condition():
            if not self._context.ok():
                raise ExternalShutdownException()
            work = self._ready_work(clock_is_work)
            if work:
                self._work.extend(work[1:])
                return work[0]
            if timeout_ns == 0 or (deadline is not None and sched.world_ns >= deadline):
                raise TimeoutException()
            self._block(sched, self._wake_ns(deadline, clock_is_work), condition)
            if self._is_shutdown:
                raise ShutdownException()
            if not self._context.ok():
                raise ExternalShutdownException()
        if self._is_shutdown:
            raise ShutdownException()
        raise ConditionReachedException()

    def _block(self, sched, wake_ns: int | None, condition) -> None:
        epoch = sleep_epoch()  # a sleep that begins meanwhile may need an earlier wake: wake to recompute it
        try:
            sched.block(deadline_ns=wake_ns, ready=lambda: self._anything_ready(condition) or sleep_epoch() != epoch)
        except KeyboardInterrupt as exc:
            if type(exc) is not KeyboardInterrupt:
                raise
            # as the C wait_set.wait that real rclpy is in: the traceback ends here, not in the scheduler
            raise exc.with_traceback(None) from None

    def _still_ready(self, item) -> bool:
        entity, kind, node = item
        if kind == "sub":
            return entity.has_message() and entity._handle is not None
        if kind == "timer":
            return not entity._destroyed and entity.is_ready()
        if kind == "client":
            return entity.has_response()
        if kind == "service":
            return entity.has_request()
        if kind == "guard":
            return entity._triggered
        if kind == "waitable":
            return entity.is_ready(None)
        return True

    # -- running ----------------------------------------------------------------------------------------------------
    def _take(self, item):
        """Take the item's data (the message, the timer call) in the spinning thread; returns the callback to run."""
        entity, kind, node = item
        if kind == "task":
            return entity
        if kind == "clock":
            return entity.apply_clock
        if kind == "timer":
            entity.call()
            return entity.run_callback
        if kind == "sub":
            taken = entity.take()
            if taken is None:
                return None
            return lambda: entity.dispatch(*taken)
        if kind == "guard":
            entity._triggered = False
            return entity.callback
        if kind == "client":
            taken = entity.take_response()
            if taken is None:
                return None
            future, response = taken
            return lambda: future.set_result(response)
        if kind == "service":
            request, header = entity.take_request()
            return lambda: entity.send_response(entity.callback(request, entity.srv_type.Response()), header)
        if kind == "waitable":
            return self._waitable_task(entity, node)
        return None

    def _waitable_task(self, waitable, node):
        """Take a waitable's data now; its coroutine runs as a task, resumed later when it awaits (rclpy's
        handler), and its futures' done callbacks become this executor's tasks."""
        data = waitable.take_data()
        for future in waitable._futures:
            future._set_executor(self)
        task = Task(waitable.execute, (data,), executor=self)

        def run() -> None:
            task()
            if not task.done():
                self._tasks.append((task, waitable, node))
            elif task.exception() is not None:
                raise task.exception()
        return run

    def _run(self, item, call) -> None:
        """Run one callback inside its callback group."""
        entity, kind, node = item
        group = getattr(entity, "callback_group", None)
        if group is not None:
            group.beginning_execution(entity)
        try:
            call()
        finally:
            if group is not None:
                group.ending_execution(entity)
        if kind == "task" and entity.done() and entity.exception() is not None:
            raise entity.exception()


class SingleThreadedExecutor(Executor):
    """Runs callbacks in the thread that calls spin."""

    def _spin_once_impl(self, timeout_sec, condition, clock_is_work: bool) -> None:
        try:
            item = self.wait_for_ready_callbacks(timeout_sec, None, condition, clock_is_work)
        except (ShutdownException, TimeoutException, ConditionReachedException):
            return
        call = self._take(item)
        if call is not None:
            self._run(item, call)


class MultiThreadedExecutor(Executor):
    """Runs callbacks in a pool of managed worker threads; callback groups decide what may overlap (a node's
    default group is mutually exclusive, so one callback of the node at a time)."""

    def __init__(self, num_threads: int | None = None, *, context=None) -> None:
        super().__init__(context=context)
        if num_threads is None:
            num_threads = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 2)
        if num_threads == 1:
            warnings.warn("MultiThreadedExecutor is used with a single thread.\nUse the SingleThreadedExecutor "
                          "instead.")
        self._num_threads = num_threads
        self._jobs: deque = deque()
        self._workers = 0
        self._errors: list[BaseException] = []

    def can_execute(self, entity) -> bool:
        if any(job[0][0] is entity for job in self._jobs):
            return False
        return super().can_execute(entity)

    def _spin_once_impl(self, timeout_sec, condition, clock_is_work: bool) -> None:
        try:
            item = self.wait_for_ready_callbacks(timeout_sec, None, condition, clock_is_work)
        except (ExternalShutdownException, ShutdownException, TimeoutException, ConditionReachedException):
            item = None
        if item is not None:
            call = self._take(item)
            if call is not None:
                group = getattr(item[0], "callback_group", None)
                if group is not None:
                    group.beginning_execution(item[0])
                self._jobs.append((item, call))
                if self._workers < self._num_threads:
                    self._workers += 1
                    _runtime.scheduler().spawn(f"ThreadPoolExecutor-0_{self._workers - 1}", self._worker)
        if self._errors:
            raise self._errors.pop(0)

    def _worker(self) -> None:
        sched = _runtime.scheduler()
        while True:
            while not self._jobs:
                sched.block(ready=lambda: bool(self._jobs))
            item, call = self._jobs.popleft()
            group = getattr(item[0], "callback_group", None)
            try:
                call()
            except Exception as exc:  # noqa: BLE001 - re-raised by the spinning thread, as future.result() in rclpy
                self._errors.append(exc)
            finally:
                if group is not None:
                    group.ending_execution(item[0])
                self._guard_triggered = True

    def shutdown(self, timeout_sec: float | None = None, *, wait_for_threads: bool = True) -> bool:
        return super().shutdown(timeout_sec)
