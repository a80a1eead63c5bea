#!/usr/bin/env python3
"""Prints the CPUs the node sees, and those the kernel really lets it use."""
import multiprocessing
import os

import rospy

rospy.init_node("cpu_view")
print("sees", os.cpu_count(), multiprocessing.cpu_count(), sorted(os.sched_getaffinity(0)))
with open("/proc/self/status") as status:
    print("kernel", next(line.split()[1] for line in status if line.startswith("Cpus_allowed_list")))
with open("/proc/self/stat") as stat:
    print("policy", stat.read().rsplit(")", 1)[1].split()[38])  # field 41: 0 SCHED_OTHER, 3 SCHED_BATCH
