"""Minimal rospy services: the grader's world offers none, so waits time out and calls fail as rospy's would."""
from __future__ import annotations

import genpy
from rosgrade_node import runtime

from . import core, names
from .exceptions import ROSException, ROSInterruptException


class ServiceException(ROSException):
    """A service call failed."""


def wait_for_service(service: str, timeout=None) -> None:
    """No service ever appears: with a timeout, wait it out (sim time) and raise rospy's timeout error."""
    resolved = names.resolve_name(service)
    sched = runtime.scheduler
    deadline = None
    if timeout is not None:
        if isinstance(timeout, genpy.Duration):
            timeout = timeout.to_sec()
        if timeout == 0.0:
            raise ValueError("timeout must be non-zero")
        deadline = sched.world_ns + round(timeout * 1e9)
    while not core._shutdown_flag:
        if deadline is not None and sched.world_ns >= deadline:
            raise ROSException("timeout exceeded while waiting for service %s" % resolved)
        sched.block(deadline_ns=deadline, ready=lambda: core._shutdown_flag)
    raise ROSInterruptException("rospy shutdown")


class ServiceProxy:
    """A client for a service that does not exist: every call raises ServiceException."""

    def __init__(self, name: str, service_class, persistent: bool = False, headers=None) -> None:
        self.resolved_name = names.resolve_name(name)
        self.service_class = service_class

    def __call__(self, *args, **kwds):
        return self.call(*args, **kwds)

    def call(self, *args, **kwds):
        raise ServiceException("service [%s] unavailable" % self.resolved_name)

    def close(self) -> None:
        """Nothing to close."""


class Service:
    """A service nobody can call (the world makes no service calls); kept so that nodes offering one still run."""

    def __init__(self, name: str, service_class, handler, buff_size: int = 65536, error_handler=None) -> None:
        self.resolved_name = names.resolve_name(name)
        self.service_class = service_class
        self.handler = handler

    def shutdown(self, reason: str = "") -> None:
        """Nothing to unregister."""

    def spin(self) -> None:
        from .client import spin
        spin()
