#!/usr/bin/env python3
"""Prints the CPUs the node sees, those the kernel really lets it use, and the kernels its numpy runs."""
import multiprocessing
import os

import rospy

rospy.init_node("cpu_view")
print("sees", os.cpu_count(), multiprocessing.cpu_count(), sorted(os.sched_getaffinity(0)))
with open("/proc/self/status") as status:
    print("kernel", next(line.split()[1] for line in status if line.startswith("Cpus_allowed_list")))
with open("/proc/self/stat") as stat:
    print("policy", stat.read().rsplit(")", 1)[1].split()[38])  # field 41: 0 SCHED_OTHER, 3 SCHED_BATCH

import numpy
from numpy.lib.introspect import opt_func_info

print("arctan2", opt_func_info(func_name="arctan2$", signature="float64")["arctan2"]["ddd"]["current"])
print("blas", os.environ.get("OPENBLAS_CORETYPE"), numpy.dot([0.1, 0.2, 0.3, 0.7], [0.3, 0.9, 0.5, 0.1]).hex())
