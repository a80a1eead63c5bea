from launch import LaunchDescription
from launch.actions import TimerAction
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='turtlesim', executable='turtlesim_node'),
        TimerAction(period=0.3, actions=[Node(package='course_pkg', executable='square', name='late_square')]),
        TimerAction(period=0.1, actions=[Node(package='course_pkg', executable='mover', name='early_mover')]),
    ])
