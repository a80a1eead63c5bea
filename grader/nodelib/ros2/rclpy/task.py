"""rclpy.task: Future (results of service calls, spin_until_future_complete) and Task (executor coroutines)."""
from __future__ import annotations

import inspect
import sys
import weakref


class Future:
    """Represents the outcome of a task in the future."""

    def __init__(self, *, executor=None) -> None:
        self._done = False
        self._cancelled = False
        self._result = None
        self._exception: BaseException | None = None
        self._exception_fetched = False
        self._callbacks: list = []
        self._executor = None
        self._set_executor(executor)

    def __del__(self) -> None:
        if self._exception is not None and not self._exception_fetched:
            print("The following exception was never retrieved: " + str(self._exception), file=sys.stderr)

    def __await__(self):
        while not self._done:
            yield
        return self.result()

    def cancel(self) -> None:
        if not self._done:
            self._cancelled = True
        self._schedule_or_invoke_done_callbacks()

    def cancelled(self) -> bool:
        return self._cancelled

    def done(self) -> bool:
        return self._done

    def result(self):
        exception = self.exception()
        if exception:
            raise exception
        return self._result

    def exception(self):
        self._exception_fetched = True
        return self._exception

    def set_result(self, result) -> None:
        self._result = result
        self._done = True
        self._cancelled = False
        self._schedule_or_invoke_done_callbacks()

    def set_exception(self, exception) -> None:
        self._exception = exception
        self._exception_fetched = False
        self._done = True
        self._cancelled = False
        self._schedule_or_invoke_done_callbacks()

    def _schedule_or_invoke_done_callbacks(self) -> None:
        """Run done callbacks through the executor when there is one, otherwise now."""
        executor = self._executor() if self._executor is not None else None
        callbacks, self._callbacks = self._callbacks, []
        for callback in callbacks:
            if executor is not None:
                executor.create_task(callback, self)
            else:
                try:
                    callback(self)
                except Exception as e:  # noqa: BLE001 - as rclpy: one failing callback must not stop the others
                    sys.stderr.write(f"Unhandled exception in done callback: {e}\n")

    def _set_executor(self, executor) -> None:
        self._executor = None if executor is None else weakref.ref(executor)

    def add_done_callback(self, callback) -> None:
        """Add a callback run when the future is done (at once if it already is)."""
        if self._done:
            executor = self._executor() if self._executor is not None else None
            if executor is not None:
                executor.create_task(callback, self)
            else:
                callback(self)
        else:
            self._callbacks.append(callback)


class Task(Future):
    """A callback or coroutine run by an executor; a coroutine resumes each time the executor runs it."""

    def __init__(self, handler, args=None, kwargs=None, executor=None) -> None:
        super().__init__(executor=executor)
        self._handler = handler
        self._args = args or ()
        self._kwargs = kwargs or {}
        if inspect.iscoroutinefunction(handler):
            self._handler = handler(*self._args, **self._kwargs)
            self._args = self._kwargs = None
        self._executing = False

    def __call__(self) -> None:
        if self._done or self._executing:
            return
        self._executing = True
        try:
            if inspect.iscoroutine(self._handler):
                try:
                    self._handler.send(None)
                except StopIteration as e:
                    self.set_result(e.value)
                    self._handler = None
            else:
                self.set_result(self._handler(*self._args, **self._kwargs))
                self._handler = self._args = self._kwargs = None
        except Exception as e:  # noqa: BLE001 - stored and re-raised by result(), as in rclpy
            self.set_exception(e)
        finally:
            self._executing = False

    def executing(self) -> bool:
        return self._executing
