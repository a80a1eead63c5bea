"""turtlesim driven from the keyboard or by pubvel's random velocities, picked by the teleop argument."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    teleop = LaunchConfiguration('teleop')
    return LaunchDescription([
        DeclareLaunchArgument('teleop', default_value='0'),
        Node(package='turtlesim', executable='turtlesim_node', name='turtlesim'),
        Node(package='turtlesim', executable='turtle_teleop_key', name='teleop_key', output='screen',
             condition=UnlessCondition(teleop)),
        Node(package='lab2_turtlesim', executable='pubvel', name='pubvel', condition=IfCondition(teleop)),
    ])
