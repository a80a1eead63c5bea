from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    nodes = [Node(package='course_pkg', executable='mover')]
    return LaunchDescription(nodes + undefined_nodes)
