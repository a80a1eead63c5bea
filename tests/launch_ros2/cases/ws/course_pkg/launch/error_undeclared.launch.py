from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='course_pkg', executable='mover', parameters=[{'distance': LaunchConfiguration('distance')}]),
    ])
