"""Tasks started from a ROS 2 launch file ([launch] with a .launch.py): move_distance_launch's distance argument
reaches the node as an argument or as a parameter (a --params-file launch_ros writes) and scores full marks, a
launch file that hard-codes the distance loses exactly stop_position, and distance:=2 handed to a parameter declared
as a float without ParameterValue(value_type=float) stops the node as real rclpy does; square_odom_launch's two nodes
from one launch file in the ROS 2 reference package score full marks, a launch file that forgets the odometry printer
loses exactly the printing criteria; a [launch] package the submission lacks is named; a launch file's
`ros2 service call` commands are carried out by the grader when launch would run them; recordings repeat bit for bit."""
from __future__ import annotations

from pathlib import Path

import shutil

import pytest

from grader.grading import grade_task
from grader.recording import Recording
from grader.rubric import load_rubric
from grader.report import TaskReport

pytestmark = pytest.mark.slow  # nine graded tasks of one to three scenarios each, about 75 s

ROOT = Path(__file__).resolve().parents[2]
SUBMISSIONS = Path(__file__).resolve().parent / "submissions"


@pytest.fixture(scope="module")
def rubric():
    """The shipped rubric: its aliases name the ROS 2 launch files (move_turtlebot.launch.py...)."""
    return load_rubric(ROOT / "rubrics" / "move_distance_launch.toml")


def _part2_with_launch(folder: Path, launch: str) -> Path:
    """The ROS 2 reference package part2_navigation with `launch` installed as launch/square_and_odom.launch.py
    (listed in setup.py's data_files, as the course's packages install launch files)."""
    package = folder / "part2_navigation"
    shutil.copytree(ROOT / "reference_solutions_ros2" / "part2_navigation", package)
    (package / "launch").mkdir()
    shutil.copy(SUBMISSIONS / "square_odom" / launch, package / "launch" / "square_and_odom.launch.py")
    setup = (package / "setup.py").read_text()
    installed = "('share/' + package_name, ['package.xml']),"
    assert installed in setup
    (package / "setup.py").write_text(setup.replace(installed, installed + "\n        ('share/' + package_name + "
                                                    "'/launch', ['launch/square_and_odom.launch.py']),"))
    return folder


@pytest.fixture(scope="module")
def square_graded(tmp_path_factory: pytest.TempPathFactory) -> dict[str, TaskReport]:
    rubric = load_rubric(ROOT / "rubrics" / "square_odom_launch.toml")
    out = tmp_path_factory.mktemp("square")
    return {launch: grade_task(_part2_with_launch(tmp_path_factory.mktemp(launch), launch), rubric, out / launch)
            for launch in ("square_and_odom.launch.py", "square_only.launch.py")}


def _without_value_type(folder: Path) -> Path:
    """launch_distance_param with the distance passed as launch reads it: distance:=2 reaches the node as an integer."""
    shutil.copytree(SUBMISSIONS / "launch_distance_param", folder / "launch_distance_param")
    launch = folder / "launch_distance_param" / "move_distance_param" / "launch" / "move_turtlebot.launch.py"
    typed = "ParameterValue(LaunchConfiguration('distance'), value_type=float)"
    assert typed in launch.read_text()
    launch.write_text(launch.read_text().replace(typed, "LaunchConfiguration('distance')"))
    return folder / "launch_distance_param"


@pytest.fixture(scope="module")
def graded(rubric, tmp_path_factory: pytest.TempPathFactory) -> dict[str, TaskReport]:
    out = tmp_path_factory.mktemp("graded")
    found = {name: grade_task(SUBMISSIONS / name, rubric, out / name)
             for name in ("launch_distance", "launch_distance_param", "launch_distance_hardcoded")}
    untyped = _without_value_type(tmp_path_factory.mktemp("untyped"))
    found["untyped"] = grade_task(untyped, rubric, out / "untyped")
    return found


def _lost(report: TaskReport) -> set[str]:
    assert report.status == "graded", report.message
    return {c.id for c in report.criteria if c.score < c.max_score}


@pytest.mark.parametrize("name", ["launch_distance", "launch_distance_param"])
def test_references_score_full_marks(graded: dict[str, TaskReport], name: str) -> None:
    assert _lost(graded[name]) == set()
    assert graded[name].score == graded[name].max_score


def test_text_of_a_node_without_output_screen_is_said_to_go_to_the_log(graded: dict[str, TaskReport]) -> None:
    assert any("its Node has no output='screen': ros2 launch shows only its stderr" in d
               for d in graded["launch_distance"].diagnostics)
    assert not any("output=" in d for d in graded["launch_distance_param"].diagnostics)


def test_an_integer_argument_for_a_float_parameter_stops_the_node_as_rclpy_does(graded: dict[str, TaskReport]) -> None:
    report = graded["untyped"]
    assert _lost(report) == {"stop_position", "stays_stopped", "velocity_limits"}
    assert any("InvalidParameterTypeException" in d and "Trying to set parameter 'distance' to '2' of type 'INTEGER', "
               "expecting type 'DOUBLE'" in d for d in report.diagnostics)


def test_hard_coded_distance_loses_exactly_stop_position(graded: dict[str, TaskReport]) -> None:
    report = graded["launch_distance_hardcoded"]
    assert _lost(report) == {"stop_position"}
    assert any("declares no argument distance" in d for d in report.diagnostics)


def test_recordings_repeat_bit_for_bit(rubric, graded: dict[str, TaskReport], tmp_path: Path) -> None:
    again = grade_task(SUBMISSIONS / "launch_distance_param", rubric, tmp_path)
    first = graded["launch_distance_param"]
    assert [Path(p).read_bytes() for p in again.recordings] == [Path(p).read_bytes() for p in first.recordings]


def test_two_nodes_from_one_ros2_launch_file_score_full_marks(square_graded: dict[str, TaskReport]) -> None:
    report = square_graded["square_and_odom.launch.py"]
    assert _lost(report) == set()
    assert report.score == report.max_score


def test_a_forgotten_odometry_printer_loses_exactly_the_printing_criteria(square_graded: dict[str, TaskReport]) -> None:
    assert _lost(square_graded["square_only.launch.py"]) == {"pose_output", "output_rate"}


def _figure_rubric(folder: Path, package: str):
    """figure_of_eight started only from `ros2 launch <package> task1.launch.py` (the shipped rubric without its
    [[nodes]], which a submission without the launch file runs instead)."""
    text = (ROOT / "rubrics" / "figure_of_eight.toml").read_text()
    nodes = '[[nodes]]\nscript = "figure_eight.py"\n'
    assert nodes in text and 'package = "com2009_team*"' in text
    (folder / "figure_of_eight.toml").write_text(text.replace(nodes, "").replace("com2009_team*", package))
    return load_rubric(folder / "figure_of_eight.toml")


def test_a_launch_package_the_submission_lacks_is_named(tmp_path: Path) -> None:
    rubric = _figure_rubric(tmp_path, "com2009_team42")
    report = grade_task(ROOT / "reference_solutions_ros2_cmake" / "com2009_team1", rubric, tmp_path / "out")
    assert report.status == "not_found"
    assert report.message.startswith("no package named com2009_team42 in the submission (the <name> in package.xml)")


def test_the_launch_files_ros2_commands_are_carried_out_when_launch_runs_them(
        tmp_path_factory: pytest.TempPathFactory) -> None:
    """The launch tutorials' pattern against turtlesim: `ros2 service call /spawn` when turtlesim starts, and a
    teleport of the new turtle from a 1 s TimerAction, carried out by the grader at those times."""
    folder = tmp_path_factory.mktemp("turtle_rubric")
    text = (ROOT / "rubrics" / "turtle_circle.toml").read_text()
    nodes = '[[nodes]]\nscript = "turtle_circle.py"\naliases = ["move_circle.py"]\n'
    assert nodes in text
    (folder / "turtle_circle.toml").write_text(text.replace(nodes, '[launch]\nfile = "turtle_circle.launch.py"\n'))
    rubric = load_rubric(folder / "turtle_circle.toml")
    report = grade_task(SUBMISSIONS / "turtle_tutorial", rubric, tmp_path_factory.mktemp("turtle"))
    assert _lost(report) == set()
    recording = Recording.open(report.recordings[0])
    start_ns = round(rubric.scenarios[0].start_time * 1e9)
    [(spawned_ns, _)] = list(recording.messages("/rosgrade/service/spawn/request"))
    [(teleported_ns, _)] = list(recording.messages("/rosgrade/service/turtle2/teleport_absolute/request"))
    assert (spawned_ns, teleported_ns) == (start_ns, start_ns + 1_000_000_000)  # at start, and after the 1 s timer
    poses = [pose for _, pose in recording.messages("/turtle2/pose")]
    # spawned where the launch file's call asked (y through turtlesim's float screen coordinates: 1.9999997)
    assert (poses[0].x, poses[0].y) == (2.0, pytest.approx(2.0, abs=1e-6))
    assert (poses[-1].x, poses[-1].y) == (5.0, 5.0)  # then teleported
