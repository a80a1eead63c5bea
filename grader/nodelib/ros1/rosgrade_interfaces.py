"""The submission's own ROS 1 message packages in the node: ``from my_msgs.srv import AddInts`` works.

The grader gives their definitions at START (genpy._msgdefs' format: comment-free text with full type names); this
adds them to the table and makes ``pkg``, ``pkg.msg`` and ``pkg.srv`` importable (rosgrade_interface_packages).
"""
from __future__ import annotations

from genpy import _msgdefs
from genpy._builder import lazy_exports
from rosgrade_interface_packages import make_importable


class InterfaceTableError(ValueError):
    """START's interfaces are not a definition table."""


def install(payload: dict) -> None:
    """Add START's ``{"messages": {pkg/Name: text}, "services": {pkg/Name: "request---response"}}`` (built-in
    types are never replaced) and make their packages importable."""
    try:
        messages = {str(k): str(v) for k, v in payload.get("messages", {}).items() if k not in _msgdefs.MESSAGES}
        services = {str(k): str(v) for k, v in payload.get("services", {}).items() if k not in _msgdefs.SERVICES}
    except (AttributeError, TypeError) as exc:
        raise InterfaceTableError(f"START's interfaces are malformed: {exc}") from None
    _msgdefs.MESSAGES.update(messages)
    _msgdefs.SERVICES.update(services)
    packages = frozenset(name.split("/")[0] for name in (*messages, *services))
    make_importable(packages, ("msg", "srv"), lazy_exports, "rosgrade's genpy")
