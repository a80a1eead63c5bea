from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='com2009_team99', executable='figure_eight', name='figure_eight', output='screen'),
    ])
