from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown
from launch_ros.actions import Node


def generate_launch_description():
    square = Node(package='course_pkg', executable='square', name='square')
    return LaunchDescription([
        square,
        RegisterEventHandler(OnProcessExit(target_action=square, on_exit=[
            LogInfo(msg='square done, shutting down'), EmitEvent(event=Shutdown(reason='square finished'))])),
    ])
