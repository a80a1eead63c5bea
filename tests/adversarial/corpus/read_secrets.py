#!/usr/bin/env python3
import sys
import rospy
rospy.init_node("reader")
for path in sys.argv[1:] + ["/etc/shadow"]:
    try:
        with open(path) as handle:
            print(f"READ {path}: {handle.read(40)!r}")
    except OSError as exc:
        print(f"cannot read {path}: {type(exc).__name__}: {exc}")
