"""Assignment 2 Task 1: the figure of eight, as the markers start it (ros2 launch com2009_team1 task1.launch.py)."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='com2009_team1', executable='figure_eight.py', name='figure_eight', output='screen'),
    ])
