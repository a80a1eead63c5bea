from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('gain', default_value='0.5'),
        DeclareLaunchArgument('label', default_value='007'),
        Node(package='course_pkg', executable='mover', name='typed', namespace='/',
             parameters=[{'flag': True, 'count': 3, 'ratio': 0.25, 'names': ['a', 'b'], 'ints': [1, 2, 3],
                          'mixed': [1, 2.5], 'pid': {'kp': 1.0, 'ki': 0.0}, 'text': 'hello world',
                          'gain': LaunchConfiguration('gain'),
                          'label': ParameterValue(LaunchConfiguration('label'), value_type=str),
                          'number_text': '42'}]),
    ])
