from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import (FileContent, IfElseSubstitution, LaunchConfiguration, NotEqualsSubstitution,
                                  PathJoinSubstitution)
from launch.utilities import perform_substitutions
from launch_ros.actions import Node, SetParametersFromFile
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def laps_node(context):
    laps = perform_substitutions(context, [LaunchConfiguration('laps')])
    return [Node(package='course_pkg', executable='square', name='square', arguments=['--laps', laps])]


def generate_launch_description():
    share = FindPackageShare('course_pkg')
    return LaunchDescription([
        DeclareLaunchArgument('fast', default_value='false'),
        DeclareLaunchArgument('laps', default_value='2'),
        SetParametersFromFile(PathJoinSubstitution([share, 'config', 'colors.yaml'])),
        Node(package='course_pkg', executable='mover', name='mover',
             parameters=[{'speed': IfElseSubstitution(LaunchConfiguration('fast'), '0.26', '0.1'),
                          'two_laps': NotEqualsSubstitution(LaunchConfiguration('laps'), '1'),
                          'urdf': ParameterValue(FileContent(PathJoinSubstitution([share, 'config', 'robot.urdf'])),
                                                 value_type=str)}]),
        OpaqueFunction(function=laps_node),
    ])
