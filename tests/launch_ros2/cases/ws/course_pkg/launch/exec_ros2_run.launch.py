# Nodes started by ExecuteProcess as course launch files start them: `ros2 run` with its own arguments, a parameter
# file and remap rules, through a shell as one command line, after a TimerAction and after another's exit.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessExit
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('course_pkg'), 'config', 'params.yaml'])
    mover = ExecuteProcess(cmd=['ros2', 'run', 'course_pkg', 'mover', 'fast', '--ros-args', '-r', '__node:=driver',
                                '-p', ['speed:=', LaunchConfiguration('speed')], '--params-file', params],
                           output='screen')
    return LaunchDescription([
        DeclareLaunchArgument('speed', default_value='0.2'),
        mover,
        ExecuteProcess(cmd=['ros2 run course_pkg talker --ros-args -r __ns:=/team7 -r chatter:=news '
                            '-p "greeting:=hello there"'], shell=True),
        TimerAction(period=1.5, actions=[ExecuteProcess(cmd=['ros2', 'run', 'course_pkg', 'listener'])]),
        RegisterEventHandler(OnProcessExit(target_action=mover, on_exit=[
            ExecuteProcess(cmd=['ros2', 'run', 'course_pkg', 'square', '--ros-args', '-p', 'side:=2.0'])])),
    ])
