#!/usr/bin/env python3
"""Probe 6: get_logger() lines (format, stream, severities), throttle_duration_sec, once, skip_first, warn().

Logging goes to stderr as '[LEVEL] [<wall s.ns>] [name]: msg'; print to stdout. Throttling is on the wall clock:
calls with no time in between print only the first, a call 1.2 s of wall time later prints again.
"""
import time

import rclpy
from rclpy.logging import LoggingSeverity
from rclpy.node import Node


def show(label, fn):
    try:
        value = fn()
        print(label, "->", repr(value))
    except Exception as e:
        print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))


rclpy.init()
node = Node("p06_logging")
log = node.get_logger()
while node.get_clock().now().nanoseconds == 0:
    rclpy.spin_once(node, timeout_sec=0.01)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
print("logger name", log.name)
print("effective level", log.get_effective_level())
log.debug("debug is hidden by default")
log.info("info message")
log.warning("warning message")
log.error("error message")
log.fatal("fatal message")
log.info("x = %.3f (m), y = %.3f (m)" % (1.0, -0.5))
log.info(f"multi\nline")
show("info returns", lambda: log.info("returned value"))
show("info(123)", lambda: log.info(123))
show("info('a %s', 1)", lambda: log.info("a %s", 1))
log.warn("warn() is deprecated")
print("print goes to stdout")

for i in range(5):
    log.info(f"throttled 1 s: call {i}", throttle_duration_sec=1)
time.sleep(1.2)
log.info("throttled 1 s: after 1.2 s wall", throttle_duration_sec=1)
for i in range(3):
    log.info(f"once A {i}", once=True)
    log.info(f"once B {i}", once=True)
    log.info(f"skip_first {i}", skip_first=True)
show("once and throttle together", lambda: log.info("both", once=True, throttle_duration_sec=1))
show("skip_first and once together", lambda: log.info("both", once=True, skip_first=True))

show("set_level(DEBUG)", lambda: log.set_level(LoggingSeverity.DEBUG))
log.debug("debug after set_level")
child = log.get_child("part")
print("child name", child.name)
child.info("from the child")
rclpy.shutdown()
print("end")
