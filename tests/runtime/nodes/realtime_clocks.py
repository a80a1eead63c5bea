#!/usr/bin/env python3
# Clocks and timed waits other than time.*: each must follow sim time and cost no wall time.
import asyncio
import datetime
import select
import threading
import time

import rospy

rospy.init_node("realtime_clocks")
rospy.sleep(0.5)


def elapsed(label, wait):
    t0, d0 = rospy.get_time(), datetime.datetime.now()
    wait()
    print(label, round(rospy.get_time() - t0, 2), round((datetime.datetime.now() - d0).total_seconds(), 2))


elapsed("asyncio.sleep(0.5)", lambda: asyncio.run(asyncio.sleep(0.5)))
elapsed("Event().wait(0.3)", lambda: threading.Event().wait(0.3))
r, w = __import__("os").pipe()
elapsed("select 0.2", lambda: select.select([r], [], [], 0.2))
poller = select.poll()
poller.register(r, select.POLLIN)
elapsed("poll 200 ms", lambda: poller.poll(200))
print("datetime is the stdlib's", type(datetime.datetime.now()) is datetime.datetime.__mro__[1],
      isinstance(datetime.datetime.now(), datetime.datetime))
print("datetime.now matches time.time", abs(datetime.datetime.now().timestamp() - time.time()) < 0.01)
print("localtime matches time.time", time.mktime(time.localtime()) == int(time.time()))
print("clock_gettime matches", abs(time.clock_gettime(time.CLOCK_REALTIME) - time.time()) < 0.02,
      abs(time.clock_gettime_ns(time.CLOCK_MONOTONIC) - time.monotonic_ns()) < 20_000_000)
print("os.times elapsed matches", abs(__import__("os").times().elapsed - time.monotonic()) < 0.01)
