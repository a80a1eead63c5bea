"""turtlesim driven from the keyboard (teleop:=1) or by pubvel's random velocities (teleop:=0, the default)."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    teleop = LaunchConfiguration('teleop')
    return LaunchDescription([
        DeclareLaunchArgument('teleop', default_value='0', description='1: drive turtle1 from the keyboard'),
        Node(package='turtlesim', executable='turtlesim_node', name='turtlesim'),
        Node(package='turtlesim', executable='turtle_teleop_key', name='teleop_key', output='screen',
             condition=IfCondition(teleop)),
        Node(package='lab2_turtlesim', executable='pubvel', name='pubvel', condition=UnlessCondition(teleop)),
    ])
