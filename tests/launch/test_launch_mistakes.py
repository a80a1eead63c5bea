"""The usual launch-file mistakes get a message that says what roslaunch would do and what to change, before
anything runs; the simulated world launch files map onto rosgrade robots; rubrics take a launch file or scripts."""
from __future__ import annotations

import shutil
import stat
from pathlib import Path

import pytest

from grader.cli import main
from grader.grading import grade_task
from grader.launch import LaunchError, find_packages, read_launch
from grader.launch.specs import node_specs
from grader.rubric import RubricError, load_rubric, load_rubrics

ROOT = Path(__file__).resolve().parents[2]
PIA = ROOT / "submissions_example" / "pia_launch_hardcoded" / "catkin_ws" / "src" / "hello_world"
RUBRIC = load_rubrics()["move_distance_launch"]
GOOD_NODE = '<node pkg="hello_world" type="move_turtlebot.py" name="mover" args="0.2 0 $(arg distance)"/>'


@pytest.fixture()
def package(tmp_path: Path) -> Path:
    """A copy of a student's catkin package (hello_world) with move_turtlebot.py, ready to be broken."""
    folder = tmp_path / "submission" / "src" / "hello_world"
    shutil.copytree(PIA, folder)
    return folder


def _launch_file(package: Path, body: str) -> Path:
    path = package / "launch" / "move_turtlebot.launch"
    path.write_text(f'<launch>\n  <arg name="distance" default="3"/>\n  {body}\n</launch>\n')
    return path


def _graded(package: Path, tmp_path: Path):
    return grade_task(package.parents[1], RUBRIC, tmp_path / "out")


def test_missing_launch_file_is_not_found_with_the_names_tried(package, tmp_path):
    (package / "launch" / "move_turtlebot.launch").unlink()
    report = _graded(package, tmp_path)
    assert report.status == "not_found"
    assert "move_turtlebot.launch" in report.message and "launch/ folder" in report.message


def test_pkg_that_is_the_folder_name_not_package_xml(package, tmp_path):
    _launch_file(package, GOOD_NODE.replace('pkg="hello_world"', 'pkg="catkin_ws"'))
    report = _graded(package, tmp_path)
    assert report.status == "error"
    assert 'pkg="catkin_ws" is not your package\'s name' in report.message
    assert "package.xml says <name>hello_world</name>" in report.message
    assert "move_turtlebot.launch line 3" in report.message


def test_type_without_the_py_extension(package, tmp_path):
    _launch_file(package, GOOD_NODE.replace('type="move_turtlebot.py"', 'type="move_turtlebot"'))
    report = _graded(package, tmp_path)
    assert report.status == "error"
    assert 'type="move_turtlebot" matches no file' in report.message
    assert 'write type="move_turtlebot.py"' in report.message


def test_type_that_is_no_script_lists_the_package_scripts(package, tmp_path):
    _launch_file(package, GOOD_NODE.replace('type="move_turtlebot.py"', 'type="mover.py"'))
    report = _graded(package, tmp_path)
    assert "matches no file in package hello_world (its Python scripts: move_turtlebot.py)" in report.message


def test_script_without_chmod_is_refused_as_roslaunch_does(package, tmp_path):
    _launch_file(package, GOOD_NODE)
    script = package / "scripts" / "move_turtlebot.py"
    script.chmod(script.stat().st_mode & ~(stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH))
    report = _graded(package, tmp_path)
    assert report.status == "error"
    assert "Cannot locate node of type [move_turtlebot.py]" in report.message
    assert "chmod +x scripts/move_turtlebot.py" in report.message


def test_script_without_chmod_runs_with_python3_when_the_rubric_allows(package):
    path = _launch_file(package, GOOD_NODE)
    script = package / "scripts" / "move_turtlebot.py"
    script.chmod(0o644)
    packages = find_packages(package.parents[1])
    nodes, notes = node_specs(read_launch(path, {}, packages), packages, allow_not_executable=True)
    assert nodes[0].script == script
    assert any("ran it with python3 anyway" in n for n in notes)


def test_xml_syntax_error_names_the_line(package, tmp_path):
    _launch_file(package, GOOD_NODE.replace("/>", ">"))
    report = _graded(package, tmp_path)
    assert report.status == "error"
    assert "move_turtlebot.launch: invalid XML: mismatched tag: line 4" in report.message


@pytest.mark.parametrize(("node", "says"), [
    ('<node pkg="turtlesim" type="draw_square" name="square"/>',
     'type="draw_square" is not a node of turtlesim the grader provides; it provides turtlesim_node, '
     'turtle_teleop_key and mimic'),
    ('<node pkg="turtlebot3_teleop" type="turtlebot3_teleop_key" name="teleop"/>',
     "package turtlebot3_teleop is not available in the grader"),
])
def test_nodes_of_other_packages_are_not_available_with_file_and_line(package, node, says):
    path = _launch_file(package, node)
    packages = find_packages(package.parents[1])
    with pytest.raises(LaunchError, match="move_turtlebot.launch line 3") as caught:
        node_specs(read_launch(path, {}, packages), packages)
    assert says in str(caught.value)


def test_an_undeclared_task_arg_is_reported(package):
    _launch_file(package, GOOD_NODE)
    report_args = read_launch(package / "launch" / "move_turtlebot.launch", {"speed": "1"},
                              find_packages(package.parents[1])).args
    assert report_args == {"distance": "3"}


@pytest.mark.parametrize(("include", "robot", "pose"), [
    ('<include file="$(find turtlebot3_gazebo)/launch/turtlebot3_world.launch"/>', "turtlebot3_waffle",
     (-2.0, -0.5, 0.0)),
    ('<include file="$(find turtlebot3_gazebo)/launch/turtlebot3_empty_world.launch">'
     '<arg name="model" value="burger"/><arg name="x_pos" value="1.5"/></include>', "turtlebot3_burger",
     (1.5, 0.0, 0.0)),
    ('<include file="$(find husky_gazebo)/launch/husky_empty_world.launch"><arg name="yaw" value="1.57"/></include>',
     "husky_a200", (0.0, 0.0, 1.57)),
])
def test_simulator_world_files_map_onto_rosgrade_robots(package, include, robot, pose):
    launch = read_launch(_launch_file(package, include), {}, find_packages(package.parents[1]))
    world = launch.worlds[0]
    assert (world.robot, (world.x, world.y, world.yaw)) == (robot, pose)


@pytest.mark.slow
def test_a_world_file_for_another_robot_is_reported_and_the_rubric_robot_is_graded(package, tmp_path):
    _launch_file(package, '<include file="$(find husky_gazebo)/launch/husky_empty_world.launch"/>\n  ' + GOOD_NODE)
    short = RUBRIC.scenarios[0].model_copy(update={"duration": 3.0})
    report = grade_task(package.parents[1], RUBRIC.model_copy(update={"scenarios": [short]}), tmp_path / "out")
    assert report.status == "graded"
    assert any("husky_gazebo/launch/husky_empty_world.launch starts a husky_a200, but this task is graded on a "
               "turtlebot3_waffle" in d for d in report.diagnostics)


@pytest.mark.slow
def test_text_of_a_node_without_output_screen_is_read_and_the_student_told(tmp_path):
    reference = tmp_path / "reference"
    shutil.copytree(ROOT / "reference_solutions", reference)
    launch = reference / "launch" / "square_and_odom.launch"
    launch.write_text(launch.read_text().replace('name="odom_subscriber" output="screen"', 'name="odom_subscriber"'))
    rubric = load_rubrics()["square_odom_launch"]
    short = rubric.scenarios[0].model_copy(update={"duration": 5.0})
    report = grade_task(reference, rubric.model_copy(update={"scenarios": [short]}), tmp_path / "out")
    hidden = [d for d in report.diagnostics if 'no output="screen"' in d]
    assert hidden == [d for d in hidden if d.startswith("odom_subscriber.py wrote text")] and len(hidden) == 1
    assert next(c for c in report.criteria if c.id == "pose_output").score > 0


def test_a_wrong_arg_to_a_world_file_is_an_unused_arg(package):
    path = _launch_file(package, '<include file="$(find turtlebot3_gazebo)/launch/turtlebot3_world.launch">'
                                 '<arg name="x" value="1"/></include>')
    with pytest.raises(LaunchError, match=r"unused args \[x\]"):
        read_launch(path, {}, {})


@pytest.mark.parametrize(("tag", "says"), [
    ('<machine name="robot" address="10.0.0.2"/>', "<machine> starts nodes on other computers"),
    ('<test test-name="t" pkg="hello_world" type="t.py"/>', "<test> starts a rostest"),
    ('<param name="robot_description" command="xacro robot.urdf.xacro"/>', "runs a program at launch time"),
    ('<rosparam command="delete" param="x"/>', "only command=\"load\""),
])
def test_what_would_run_programs_at_launch_is_refused(package, tag, says):
    with pytest.raises(LaunchError, match="line 3") as caught:
        read_launch(_launch_file(package, tag), {}, {})
    assert says in str(caught.value)


@pytest.mark.parametrize(("expression", "says"), [
    ("__import__('os').system('true')", "double underscores"),
    ("(lambda: 1)()", "Lambda is not allowed"),
    ("'x'._x", "attribute _x is not allowed"),
    ("('x' * 1000) * 1000", "more than 100000 items"),
    ("[0] * (distance * 100000)", "more than 100000 items"),
    ("2 ** (distance * 100)", "exponents above 64"),
    ("[c for c in 'ab']", "ListComp is not allowed"),
])
def test_eval_runs_only_plain_expressions(package, expression, says):
    path = _launch_file(package, f'<param name="p" value="$(eval {expression})"/>')
    with pytest.raises(LaunchError, match="line 3") as caught:
        read_launch(path, {}, {})
    assert says in str(caught.value)


@pytest.mark.parametrize("tag", [
    '<param name="secret" textfile="/etc/hostname"/>',
    '<rosparam file="$(dirname)/../../../../outside.yaml"/>',
    '<include file="/etc/outside.launch"/>',
])
def test_a_graded_launch_file_reads_nothing_outside_the_submission(package, tag):
    (package.parents[2] / "outside.yaml").write_text("leak: 1\n")
    path = _launch_file(package, tag)
    with pytest.raises(LaunchError, match="outside your submission"):
        read_launch(path, {}, find_packages(package.parents[1]), confine_to=package.parents[1])
    if "include" not in tag and "hostname" not in tag:
        assert read_launch(path, {}, {}).params == {"/leak": 1}  # unconfined (the CLI), as roslaunch reads it


def test_a_yaml_alias_bomb_is_refused(package):
    levels = "".join(f"l{i + 1}: &l{i + 1} [{', '.join([f'*l{i}'] * 10)}]\n" for i in range(6))
    (package / "launch" / "bomb.yaml").write_text(f"l0: &l0 [1, 2]\n{levels}")
    path = _launch_file(package, '<rosparam file="$(dirname)/bomb.yaml"/>')
    with pytest.raises(LaunchError, match="more than 100000 items"):
        read_launch(path, {}, {})


def test_include_cycle_is_caught(package):
    path = package / "launch" / "loop.launch"
    path.write_text('<launch>\n  <include file="$(dirname)/loop.launch"/>\n</launch>\n')
    with pytest.raises(LaunchError, match="nest deeper"):
        read_launch(path, {}, {})


def test_include_fan_out_is_capped(package):
    folder = package / "launch"
    (folder / "level7.launch").write_text("<launch/>\n")
    for level in range(7):  # each level includes the next twice: 2 ** 7 files in all
        include = f'<include file="$(dirname)/level{level + 1}.launch"/>'
        (folder / f"level{level}.launch").write_text(f"<launch>\n  {include}\n  {include}\n</launch>\n")
    with pytest.raises(LaunchError, match="more than 64 files"):
        read_launch(folder / "level0.launch", {}, {})


def test_too_many_nodes_are_refused_before_any_process_starts(package):
    nodes = "\n".join(GOOD_NODE.replace('name="mover"', f'name="mover{i}"') for i in range(17))
    path = _launch_file(package, nodes)
    packages = find_packages(package.parents[1])
    with pytest.raises(LaunchError, match="starts 17 nodes"):
        node_specs(read_launch(path, {}, packages), packages)


def test_a_rubric_names_nodes_or_a_launch_file(tmp_path):
    """Neither is refused; both is one task marked either way (the launch file when the submission holds it)."""
    text = (ROOT / "rubrics" / "move_distance_launch.toml").read_text()
    start, end = text.index("[launch]"), text.index("[scenario_defaults]")
    neither = tmp_path / "move_distance_launch.toml"
    neither.write_text(text[:start] + text[end:])
    with pytest.raises(RubricError, match="give at least one of them"):
        load_rubric(neither)


def test_cli_prints_params_and_nodes(capsys):
    path = PIA.parents[2] / ".." / "quinn_launch_remap" / "catkin_ws" / "src" / "hello_world" / "launch"
    assert main(["launch", str(path / "move_turtlebot.launch"), "distance:=2", "--nodes"]) == 0
    assert capsys.readouterr().out == "/move_turtlebot\n"
    assert main(["launch", str(path / "move_turtlebot.launch"), "--dump-params"]) == 0
    assert capsys.readouterr().out == "{}\n\n"


def test_cli_takes_a_package_and_a_file_name_as_roslaunch_does(capsys, monkeypatch):
    monkeypatch.chdir(ROOT / "submissions_example" / "quinn_launch_remap")
    assert main(["launch", "hello_world", "move_turtlebot.launch", "distance:=2", "--nodes"]) == 0
    assert capsys.readouterr().out == "/move_turtlebot\n"
    assert main(["launch", "hello_wrld", "move_turtlebot.launch", "--nodes"]) == 2
    assert "no package named hello_wrld" in capsys.readouterr().err


def test_cli_errors_are_one_line_with_exit_2(capsys, tmp_path):
    assert main(["launch", str(tmp_path / "none.launch"), "--nodes"]) == 2
    assert capsys.readouterr().err.count("\n") == 1
    assert main(["launch", str(tmp_path / "none.launch"), "distance=2", "--nodes"]) == 2
    assert "pass launch args as name:=value" in capsys.readouterr().err
