"""rclpy.impl: the logger implementation and severities."""
