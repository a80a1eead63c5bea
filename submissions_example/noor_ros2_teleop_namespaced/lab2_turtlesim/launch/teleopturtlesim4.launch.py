"""turtlesim in the namespace turtlesim1, as the ROS 2 launch tutorial starts it, driven from the keyboard
(teleop:=1) or by pubvel's random velocities (teleop:=0); every node in the same namespace."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    teleop = LaunchConfiguration('teleop')
    return LaunchDescription([
        DeclareLaunchArgument('teleop', default_value='0'),
        Node(package='turtlesim', namespace='turtlesim1', executable='turtlesim_node', name='sim'),
        Node(package='turtlesim', namespace='turtlesim1', executable='turtle_teleop_key', name='teleop_key',
             output='screen', condition=IfCondition(teleop)),
        Node(package='lab2_turtlesim', namespace='turtlesim1', executable='pubvel', name='pubvel',
             condition=UnlessCondition(teleop)),
    ])
