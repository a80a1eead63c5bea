"""Part 2, Exercise 5's advanced feature: the square mover and the odometry printer started together."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='part2_navigation', executable='move_square.py', name='move_square', output='screen'),
        Node(package='part2_navigation', executable='odom_subscriber.py', name='odom_subscriber', output='screen'),
    ])
