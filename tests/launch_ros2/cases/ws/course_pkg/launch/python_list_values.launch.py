from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    robot = LaunchConfiguration('robot')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='tb3'),
        Node(package='course_pkg', executable='talker', name='talker',
             parameters=[{'frames': ParameterValue(['odom', 'base_link']),
                          'topic': ParameterValue(['/', robot, '/cmd_vel']),
                          'robots': [robot, '_1'],
                          'pairs': [['a', robot], ['b']]}]),
    ])
