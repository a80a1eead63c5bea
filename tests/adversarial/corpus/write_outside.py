#!/usr/bin/env python3
import os
import sys
import rospy
rospy.init_node("writer")
here = os.path.dirname(os.path.abspath(__file__))
targets = sys.argv[1:] + [os.path.join(here, "dropped.txt"), "/etc/rosgrade-pwned", "/root/pwned", "/usr/pwned"]
for path in targets:
    try:
        with open(path, "w") as handle:
            handle.write("pwned")
        print(f"WROTE {path}")
    except OSError as exc:
        print(f"cannot write {path}: {type(exc).__name__}: {exc}")
with open("scratch.txt", "w") as handle:   # its own private folder works
    handle.write("ok")
print("scratch ok")
