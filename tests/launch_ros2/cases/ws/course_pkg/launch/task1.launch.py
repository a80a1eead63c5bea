from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='course_pkg', executable='figure_of_eight', name='figure_of_eight', output='screen'),
    ])
