"""Seed 003 in ROS 2: ros2 launch turtlebot_launch move_turtlebot.launch.py distance:=2 drives to x = 2 m."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    distance = LaunchConfiguration('distance')
    return LaunchDescription([
        DeclareLaunchArgument('distance', default_value='3.0', description='x (m) at which the robot stops'),
        Node(
            package='turtlebot_launch',
            executable='move_turtlebot',
            output='screen',
            # distance:=2 is read as the integer 2; the node declares a float, so say which type it is
            parameters=[{'distance': ParameterValue(distance, value_type=float)}],
        ),
    ])
