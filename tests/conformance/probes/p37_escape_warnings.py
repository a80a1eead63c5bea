#!/usr/bin/env python3
"""Probe 37: source with invalid escape sequences, as students write regexes ("\d") and Windows paths: Noetic's
Python compiles it without a word (Python >= 3.12 would print a SyntaxWarning for each)."""
import re

import rospy

rospy.init_node("p37_escape_warnings")
print("regex", re.match("(\d+\.\d+) m", "1.25 m").group(1))
print("path", "C:\data\scans".split("\\"))
print("octal", [hex(ord(c)) for c in "\777"])
