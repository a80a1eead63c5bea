"""Probe: Time.now() is zero right after init_node, then moves in 10 ms /clock steps; time.time follows sim time."""
import time

import rospy

rospy.init_node("timeprobe")
print("first", rospy.Time.now().to_nsec(), rospy.Time.now() is rospy.Time.now())
for _ in range(3):
    print("now", rospy.Time.now().to_nsec())
w0 = time.time()
rospy.sleep(0.05)
print("after_sleep", rospy.get_rostime().to_nsec(), round((time.time() - w0) * 1e9))
t0 = time.monotonic()
time.sleep(0.0123)
print("time_sleep_ns", round((time.monotonic() - t0) * 1e9))
rospy.loginfo("done %d", 7)
