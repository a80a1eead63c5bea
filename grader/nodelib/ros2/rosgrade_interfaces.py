"""The submission's own ROS 2 interface packages in the node: ``from my_interfaces.srv import MyNumberGame`` works.

The grader gives their definitions at START (rosgrade_rosidl's table format); this adds them to the table and makes
``pkg``, ``pkg.msg``, ``pkg.srv`` and ``pkg.action`` importable (rosgrade_interface_packages).
"""
from __future__ import annotations

from rosgrade_interface_packages import make_importable
from rosgrade_rosidl._extra import register
from rosgrade_rosidl._package import lazy_module


def install(payload: dict) -> None:
    """Add START's interfaces and make their packages importable."""
    make_importable(frozenset(register(payload)), ("msg", "srv", "action"), lazy_module, "rosgrade's rosidl runtime")
