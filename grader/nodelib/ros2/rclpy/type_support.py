"""rclpy.type_support: the checks rclpy makes before creating an endpoint, with real rclpy's errors for a class that
is not a ROS 2 interface (an int, a ROS 1 message, a service where a message belongs, or the other way round)."""
from __future__ import annotations

from .exceptions import NoTypeSupportImportedException

_ROS1_HINT = (" This might be a ROS 1 message type but it should be a ROS 2 message type."
              " Make sure to source your ROS 2 workspace after your ROS 1 workspace.")


def check_for_type_support(msg_or_srv_type) -> None:
    """Import the type support; AttributeError (with rclpy's ROS 1 hint) for anything without one."""
    # Jazzy's rclpy reads the type support from the class's metaclass: for a class that is no ROS 2 type (int) the
    # error names `type`.
    try:
        support = msg_or_srv_type.__class__._TYPE_SUPPORT
    except AttributeError as exc:
        exc.args = (exc.args[0] + _ROS1_HINT, *exc.args[1:])
        raise
    if support is None:
        msg_or_srv_type.__class__.__import_type_support__()
    if msg_or_srv_type.__class__._TYPE_SUPPORT is None:
        raise NoTypeSupportImportedException()


def check_is_valid_msg_type(msg_type) -> None:
    # rosgrade's message classes have no C converters; the converter attributes (None here) mark a message class.
    check_for_type_support(msg_type)
    if not hasattr(msg_type, "_CREATE_ROS_MESSAGE"):
        raise RuntimeError(f"The message type provided is not valid ({msg_type}), this might be a service or action")


def check_is_valid_srv_type(srv_type) -> None:
    check_for_type_support(srv_type)
    if getattr(srv_type, "Request", None) is None or getattr(srv_type, "Response", None) is None:
        raise RuntimeError(f"The service type provided is not valid ({srv_type}), this might be a message or action")
