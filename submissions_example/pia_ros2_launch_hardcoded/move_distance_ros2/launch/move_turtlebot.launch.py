from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='move_distance_ros2', executable='move_turtlebot', output='screen',
             parameters=[{'speed': 0.2, 'distance': 3.0}]),
    ])
