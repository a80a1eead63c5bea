"""A launch file's ExecuteProcess that starts a node (`ros2 run PKG EXE`, `python3 SCRIPT.py`, a script by its path)
is that node in the run, with exactly the arguments `ros2 run` hands the executable (its own, no launch name or
parameter file) and launch's start time; a shell command line is split as the shell would split one simple command,
and a compound one, `ros2 launch`, or a package the submission lacks are said not to be run; a graded square_odom_launch
whose odometry printer starts through `ros2 run` in a shell scores full marks."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from grader.grading import grade_task
from grader.launch.ros2_exec import ExecError, shell_words
from grader.launch.ros2_specs import ros2_node_specs
from grader.report import TaskReport
from grader.rubric import load_rubric
from grader.runtime.spec import Start
from grader.workspace import read_workspace
from tests.launch_ros2.test_launch_ros2_tasks import _part2_with_launch

ROOT = Path(__file__).resolve().parents[2]
LAUNCH = '''
from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node
from launch_ros.substitutions import ExecutableInPackage


def generate_launch_description():
    square = ExecuteProcess(cmd=['ros2', 'run', 'part2_navigation', 'move_square', 'fast', '--ros-args', '-r',
                                 '__node:=mover', '-p', 'side:=1.5', '--params-file', 'part2_navigation/p.yaml'])
    return LaunchDescription([
        TimerAction(period=2.0, actions=[square]),
        ExecuteProcess(cmd=['python3 -u part2_navigation/part2_navigation/odom_subscriber.py --verbose'], shell=True),
        RegisterEventHandler(OnProcessExit(target_action=square, on_exit=[
            ExecuteProcess(cmd=['part2_navigation/part2_navigation/move_circle.py'])])),
        ExecuteProcess(cmd=['ros2', 'run', 'turtlesim', 'turtlesim_node']),
        ExecuteProcess(cmd=['ros2', 'run', 'turtlesim', 'turtle_teleop_key']),
        ExecuteProcess(cmd=['ros2 run part2_navigation odom_subscriber > odom.txt'], shell=True),
        ExecuteProcess(cmd=['ros2', 'run', 'part2_navigation', 'no_such_node']),
        ExecuteProcess(cmd=['ros2', 'launch', 'part2_navigation', 'other.launch.py']),
        ExecuteProcess(cmd=['python3', '-m', 'part2_navigation.move_square']),
        ExecuteProcess(cmd=['rviz2']),
        ExecuteProcess(cmd=['sleep', '2']),
        ExecuteProcess(cmd=[ExecutableInPackage('move_circle', 'part2_navigation'), 'slow']),
    ])
'''


@pytest.fixture(scope="module")
def evaluated(tmp_path_factory: pytest.TempPathFactory):
    folder = tmp_path_factory.mktemp("ws")
    package = folder / "part2_navigation"
    shutil.copytree(ROOT / "reference_solutions_ros2" / "part2_navigation", package)
    (package / "p.yaml").write_text("/**:\n  ros__parameters:\n    side: 2.0\n")
    (package / "launch").mkdir()
    (package / "launch" / "exec.launch.py").write_text(LAUNCH)
    setup = (package / "setup.py").read_text()
    installed = "('share/' + package_name, ['package.xml']),"
    (package / "setup.py").write_text(setup.replace(installed, installed + "\n        ('share/' + package_name + "
                                                    "'/launch', ['launch/exec.launch.py']),"))
    return ros2_node_specs(package / "launch" / "exec.launch.py", read_workspace(folder), {}, "\x1b[A")


@pytest.mark.slow  # one confined evaluation of the launch file, about 0.5 s
def test_ros2_run_and_scripts_start_the_submissions_nodes_with_ros2_runs_argv(evaluated) -> None:
    specs, _, _ = evaluated
    assert [spec.script.name for spec in specs] == ["odom_subscriber.py", "turtle_teleop_key_ros2.py", "move_circle.py",
                                                    "move_square.py", "move_circle.py", "turtlesim_rotate_absolute.py"]
    printer, teleop, installed, square, circle, _ = specs
    assert installed.args == ("slow",) and installed.entry is not None  # the installed executable's path
    assert printer.entry is None and circle.entry is None  # scripts run by their path run as files
    assert square.args[:7] == ("fast", "--ros-args", "-r", "__node:=mover", "-p", "side:=1.5", "--params-file")
    assert square.files == (("launch_params_1.yaml", b"/**:\n  ros__parameters:\n    side: 2.0\n"),)
    assert square.entry is not None and square.entry.function == "main"
    assert printer.args == ("--verbose",)
    assert teleop.stdin == "\x1b[A" and teleop.provided
    assert square.start == Start(delay_s=2.0, said="2 s after the start (TimerAction)")
    # launch names each process by its order of start: the ros2 run of move_square is its eleventh
    assert circle.start == Start(delay_s=0.0, after=3, on="exit", said="when ros2-11 exits")


@pytest.mark.slow
def test_what_is_not_run_is_said_with_why(evaluated) -> None:
    _, findings, _ = evaluated
    said = "\n".join(findings)
    assert "runs `ros2 run part2_navigation odom_subscriber > odom.txt`, which rosgrade did not run: it is not a " \
           "single command (it uses >)" in said
    assert "`ros2 run` would print: No executable found" in said
    assert "include the other launch file with IncludeLaunchDescription" in said
    assert "`python3 -m` does not run a script of the submission" in said
    assert "starts `rviz2`: rosgrade runs the nodes" in said and "starts `sleep 2`: rosgrade runs" in said
    assert "turtlesim_node" not in said  # the world, started by ros2 run as by a Node


@pytest.mark.parametrize(("line", "words"), [
    ('ros2 run pkg exe --ros-args -p "name:=a b"', ["ros2", "run", "pkg", "exe", "--ros-args", "-p", "name:=a b"]),
    ("python3 'my node.py' x", ["python3", "my node.py", "x"]),
    ("ros2 param set /sim background_r '120;'", ["ros2", "param", "set", "/sim", "background_r", "120;"]),
])
def test_one_simple_command_splits_as_a_shell_splits_it(line: str, words: list[str]) -> None:
    assert shell_words(line) == words


@pytest.mark.parametrize("line", ["ros2 run a b | tee x", "ros2 run a b && ros2 run a c", "ros2 run a b; sleep 1",
                                  "ros2 run a b &", "ros2 run a b 2>/dev/null", "ros2 run a $NODE",
                                  "ros2 run a `cat n`", "ros2 run a 'b"])
def test_anything_but_one_simple_command_is_refused(line: str) -> None:
    with pytest.raises(ExecError):
        shell_words(line)


@pytest.fixture(scope="module")
def graded(tmp_path_factory: pytest.TempPathFactory) -> TaskReport:
    rubric = load_rubric(ROOT / "rubrics" / "square_odom_launch.toml")
    folder = _part2_with_launch(tmp_path_factory.mktemp("exec"), "square_and_odom_exec.launch.py")
    return grade_task(folder, rubric, tmp_path_factory.mktemp("out"))


@pytest.mark.slow  # one graded task of two scenarios, about 20 s
def test_an_odometry_printer_started_by_ros2_run_scores_full_marks(graded: TaskReport) -> None:
    assert graded.status == "graded", graded.message
    assert {c.id for c in graded.criteria if c.score < c.max_score} == set()
    assert graded.score == graded.max_score
