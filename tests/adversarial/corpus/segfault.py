#!/usr/bin/env python3
import ctypes
import rospy
rospy.init_node("segv")
ctypes.string_at(0)
