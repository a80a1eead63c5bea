#!/usr/bin/env python3
"""Probe 1: time before and after init_node, the first clock, the cached Time.now(), Rate(10) created at time 0.

Times are printed as t=<sim seconds relative to the origin>, the origin being the time after the first
rospy.sleep(0.01) (one clock step after the first clock tick); '#REF' gives the origin's absolute value.
"""
import time

import rospy


def err(e):
    return "%s.%s: %s" % (type(e).__module__, type(e).__name__, e)


for label, call in [("Time.now", lambda: rospy.Time.now()), ("get_time", rospy.get_time),
                    ("get_rostime", rospy.get_rostime), ("Rate", lambda: rospy.Rate(10)),
                    ("spin", rospy.spin)]:
    try:
        print("before_init", label, "->", repr(call()))
    except Exception as e:
        print("before_init", label, "!!", err(e))
print("before_init is_shutdown", rospy.is_shutdown())
rospy.sleep(0.01)
print("before_init sleep(0.01) returned")

rospy.init_node("p01_time")
t = rospy.Time.now()
r = rospy.Rate(10)  # created right after init_node: at time 0 (the first clock comes a few ms later)
rate_made_at_zero = rospy.Time.now().is_zero()
print("after_init now_is_zero", t.is_zero(), "get_time", rospy.get_time(), "type", type(t).__name__)
print("after_init now_is_now", rospy.Time.now() is rospy.Time.now())
print("rate created at time zero", rate_made_at_zero, "remaining", repr(r.remaining()))

rospy.sleep(0.01)
T0 = rospy.get_time()
print("#REF %.6f" % T0)
print("after_first_sleep now_is_zero", rospy.Time.now().is_zero())


def rel():
    return "t=%.3f" % (rospy.get_time() - T0)


print("now_is_now", rospy.Time.now() is rospy.Time.now(), "now_eq_rostime", rospy.Time.now() == rospy.get_rostime())
print("time_type", type(rospy.Time.now()).__name__, type(rospy.get_time()).__name__)
print("T0_on_clock_grid", round(T0 * 100) == round(T0 * 100, 6))

# Rate created at time 0: its first sleep returns at once, then 0.1 s spacing.
for i in range(5):
    print("rate_at_zero iter", i, rel())
    r.sleep()

# rospy.sleep wakes on the first tick at or after the deadline.
a = rospy.get_time()
rospy.sleep(0.3)
print("rospy.sleep(0.3) advanced %.2f" % (rospy.get_time() - a))
a = rospy.get_time()
rospy.sleep(0.0)
print("rospy.sleep(0) advanced %.2f" % (rospy.get_time() - a))
a = rospy.get_time()
rospy.sleep(-1.0)
print("rospy.sleep(-1) advanced %.2f" % (rospy.get_time() - a))
a = rospy.get_time()
rospy.sleep(rospy.Duration(0, 150000000))
print("rospy.sleep(Duration 0.15) advanced %.2f" % (rospy.get_time() - a))

# A Rate created on a running clock: no double iteration.
r2 = rospy.Rate(10)
for i in range(3):
    print("rate_running iter", i, rel())
    r2.sleep()
print("rate_running remaining_in_range", 0 < r2.remaining().to_sec() <= 0.1)

# Time stands still between ticks: distinct values seen while polling for 0.2 s are 10 ms apart.
seen = []
a = rospy.get_time()
while rospy.get_time() - a < 0.2:
    v = rospy.get_time()
    if not seen or v != seen[-1]:
        seen.append(v)
steps = sorted({round(b - a_, 3) for a_, b in zip(seen, seen[1:])})
# (real rospy can skip a tick while the busy loop holds the GIL, so only the smallest step is compared)
print("smallest step", steps[0] if steps else None, "all steps multiples of 10 ms",
      all(abs(x * 100 - round(x * 100)) < 1e-6 for x in steps))

a = rospy.get_time()
time.sleep(0.3)
print("time.sleep(0.3) advanced about %.1f" % (rospy.get_time() - a))
print("done", rel())
