"""rclpy.action: action servers and clients, made of services and topics routed by the grader as rcl_action's are."""
from .client import ActionClient  # noqa: F401
from .graph import (get_action_client_names_and_types_by_node, get_action_names_and_types,  # noqa: F401
                    get_action_server_names_and_types_by_node)
from .server import ActionServer, CancelResponse, GoalResponse  # noqa: F401
