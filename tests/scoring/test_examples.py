"""The example submissions and reference solutions agree with the rubrics (the end-to-end runs need the runtime)."""
from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from grader.rubric import load_rubrics
from grader.runtime.client_library import ROS1, client_library

ROOT = Path(__file__).resolve().parents[2]
RUBRICS = load_rubrics()
EXPECTED = tomllib.loads((ROOT / "submissions_example" / "EXPECTED.toml").read_text(encoding="utf-8"))


def _scripts(folder: Path) -> set[str]:
    return {p.name for p in folder.rglob("*.py")}


def _reference_scripts(task: str) -> list[Path]:
    """The reference node(s) of a task: its scripts, or the ones its reference launch file starts."""
    rubric = RUBRICS[task]
    folder = ROOT / ("reference_solutions_turtlesim" if rubric.robot == "turtlesim" else "reference_solutions")
    if rubric.nodes:  # a rubric with both runs its [[nodes]] in a submission without the launch file
        return [folder / node.script for node in rubric.nodes]
    from grader.launch import find_packages, read_launch

    packages = find_packages(folder)
    launch = read_launch(next(folder.rglob(rubric.launch.file)), rubric.launch.args, packages)
    # the student's own nodes (turtlesim's are the world and the grader's), else every script of its packages
    started = [next(packages[node.pkg].rglob(node.type)) for node in launch.nodes if node.pkg in packages]
    return started or [script for package in packages.values() for script in package.rglob("*.py")]


# ROS 2-only tasks whose reference is an ament_python package of rclpy nodes (its folder).
ROS2_TASKS = {"add_two_ints": "reference_solutions_ros2/py_srvcli", "fibonacci": "reference_solutions_ros2/py_action",
              "fibonacci_client": "reference_solutions_ros2/py_action",
              "add_two_ints_client": "reference_solutions_ros2/py_srvcli",
              "turtle_spawn_draw": "reference_solutions_turtlesim_ros2/turtlesim_tutorials",
              "turtle_rotate_absolute": "reference_solutions_turtlesim_ros2/turtlesim_tutorials"}
# ROS 2-only tasks whose reference is a COM2009 ament_cmake package: scripts/ installed by install(PROGRAMS).
ROS2_CMAKE_TASKS = {"param_circle": "part3_beyond_basics", "number_game": "part4_services",
                    "number_game_client": "part4_services", "explore_forward": "part5_actions"}


@pytest.mark.parametrize("task", sorted(RUBRICS))
def test_every_task_has_an_executable_reference_node(task: str) -> None:
    if task in ROS2_TASKS:
        package = ROOT / ROS2_TASKS[task]
        for node in RUBRICS[task].nodes:
            text = next(package.rglob(node.script)).read_text(encoding="utf-8")
            assert "rclpy" in text and f"{node.script[:-3]} = " in (package / "setup.py").read_text()
            compile(text, node.script, "exec")
        return
    if task in ROS2_CMAKE_TASKS:
        package = ROOT / "reference_solutions_ros2_cmake" / ROS2_CMAKE_TASKS[task]
        for node in RUBRICS[task].nodes:
            script = package / "scripts" / node.script
            text = script.read_text(encoding="utf-8")
            assert text.startswith("#!/usr/bin/env python3\n") and "rclpy" in text and script.stat().st_mode & 0o111
            assert f"scripts/{node.script}" in (package / "CMakeLists.txt").read_text()
            compile(text, node.script, "exec")
        return
    for path in _reference_scripts(task):
        text = path.read_text(encoding="utf-8")
        assert text.startswith("#!/usr/bin/env python3\n") and "rospy" in text
        compile(text, str(path), "exec")


@pytest.mark.parametrize("student", sorted(EXPECTED))
def test_expected_outcomes_name_real_students_tasks_and_criteria(student: str) -> None:
    folder = ROOT / "submissions_example" / student
    for task, expect in EXPECTED[student].items():
        rubric = RUBRICS[task]
        ids = {c.id for c in rubric.criteria}
        assert set(expect["lose"]) | set(expect.get("keep", [])) <= ids
        assert not set(expect["lose"]) & set(expect.get("keep", []))
        assert set(expect.get("says", {})) <= set(expect["lose"])
        launch = {rubric.launch.file, *rubric.launch.aliases} if rubric.launch is not None else set()
        names = launch | {n.script for n in rubric.nodes} | {a for n in rubric.nodes for a in n.aliases}
        assert names & {p.name for p in folder.rglob("*")}, f"{student} has no launch file or script for {task}"
    for path in folder.rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        # rosrun runs a ROS 1 script itself; `ros2 run` starts a ROS 2 module through its entry point
        if client_library(path) == ROS1 and path.name not in ("setup.py", "__init__.py"):
            assert text.startswith("#!/usr/bin/env python3\n"), path
        compile(text, str(path), "exec")
