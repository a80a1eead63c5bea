from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    child = PathJoinSubstitution([FindPackageShare('course_pkg'), 'launch', 'include_child.launch.py'])
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(child),
                                 launch_arguments={'robot_name': 'alpha'}.items()),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(child),
                                 launch_arguments={'robot_name': 'beta', 'rate': '5'}.items()),
    ])
