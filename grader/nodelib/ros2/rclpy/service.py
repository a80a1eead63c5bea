"""rclpy.service.Service: accepted so nodes that offer one run; the grader routes calls to the world only, so
nobody can call it (as rospy's Service under rosgrade)."""
from __future__ import annotations


class Service:
    def __init__(self, node, srv_type, srv_name: str, callback, callback_group, qos_profile) -> None:
        self.srv_type = srv_type
        self.srv_name = srv_name
        self.callback = callback
        self.callback_group = callback_group
        self.qos_profile = qos_profile

    @property
    def service_name(self) -> str:
        return self.srv_name

    @property
    def handle(self):
        return self

    def send_response(self, response, header) -> None:
        """Nothing to answer: no request ever arrives."""

    def destroy(self) -> None:
        """Nothing to unregister."""

    def __enter__(self) -> Service:
        return self

    def __exit__(self, *exc) -> None:
        self.destroy()
