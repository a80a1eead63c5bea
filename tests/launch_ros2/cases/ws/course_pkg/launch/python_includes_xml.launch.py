from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare('course_pkg')
    return LaunchDescription([
        IncludeLaunchDescription(AnyLaunchDescriptionSource(PathJoinSubstitution([share, 'launch', 'xml_groups.launch.xml'])),
                                 launch_arguments={'robot': 'tb3_1', 'use_mover': 'false'}.items()),
        IncludeLaunchDescription(AnyLaunchDescriptionSource(PathJoinSubstitution([share, 'launch', 'task2.launch.yaml']))),
    ])
