"""The workspace model: packages as colcon and catkin would build them, read from their files and never run."""
from __future__ import annotations

import time
from pathlib import Path

import pytest

from grader.launch import find_packages
from grader.workspace import WorkspaceError, read_package, read_workspace

from workspace_helpers import MANIFEST, TEMPLATE, cmake_package, write


def test_the_com2009_template_package(tmp_path: Path) -> None:
    package = read_package(cmake_package(tmp_path / "part2_navigation"))
    assert package is not None
    assert (package.name, package.build_type, package.findings) == ("part2_navigation", "ament_cmake", ())
    assert [e.name for e in package.executables] == ["move_circle.py"]  # `ros2 run` keeps the .py
    assert [(p.name, p.declared, p.root) for p in package.python_packages] == [
        ("part2_navigation_modules", True, tmp_path / "part2_navigation")]
    assert "rclpy" in package.depends


def test_the_cmake_reference_twin_reads_without_findings() -> None:
    twin = Path(__file__).resolve().parents[2] / "reference_solutions_ros2_cmake" / "part2_navigation"
    package = read_package(twin)
    assert package is not None and package.findings == ()
    assert sorted(e.name for e in package.executables) == ["move_circle.py", "move_square.py", "odom_subscriber.py"]


def test_a_program_file_that_does_not_exist(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("scripts/move_circle.py", "scripts/move_circle.py\n  scripts/gone.py")
    package = read_package(cmake_package(tmp_path / "p", "p", text))
    [finding] = package.findings
    assert "line 11" in finding and 'file INSTALL cannot find "gone.py"' in finding
    assert [e.name for e in package.executables] == ["move_circle.py"]


def test_a_modules_folder_without_init(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    (folder / "p_modules" / "__init__.py").unlink()
    package = read_package(folder)
    [finding] = package.findings
    assert "doesn't contain an '__init__.py' file" in finding and "p_modules/__init__.py" in finding
    assert package.python_packages == ()


def test_modules_not_installed_are_known_but_undeclared(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("ament_python_install_package(${PROJECT_NAME}_modules)\n", "")
    package = read_package(cmake_package(tmp_path / "p", "p", text))
    assert package.findings == ()
    assert [(p.name, p.declared) for p in package.python_packages] == [("p_modules", False)]


def test_install_package_without_find_package_ament_cmake_python(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("find_package(ament_cmake_python REQUIRED)\n", "")
    [finding] = read_package(cmake_package(tmp_path / "p", "p", text)).findings
    assert 'Unknown CMake command "ament_python_install_package"' in finding
    assert "find_package(ament_cmake_python REQUIRED)" in finding


def test_no_ament_package_call(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("ament_package()\n", "")
    [finding] = read_package(cmake_package(tmp_path / "p", "p", text)).findings
    assert "Package 'p' not found" in finding and "ament_package()" in finding


def test_project_name_other_than_the_package_name(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("project(p)", "project(ros2_pkg_template)")
    package = read_package(cmake_package(tmp_path / "p", "p", text))
    assert any("does not match current PROJECT_NAME 'ros2_pkg_template'" in f for f in package.findings)


def test_scripts_installed_as_a_directory(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace(
        "install(PROGRAMS\n  scripts/move_circle.py\n", "install(DIRECTORY scripts/ USE_SOURCE_PERMISSIONS\n")
    package = read_package(cmake_package(tmp_path / "p", "p", text))
    assert [(e.name, e.executable_install) for e in package.executables] == [("move_circle.py", True)]


def test_scripts_installed_as_plain_files(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("install(PROGRAMS", "install(FILES")
    package = read_package(cmake_package(tmp_path / "p", "p", text))
    assert [(e.name, e.executable_install) for e in package.executables] == [("move_circle.py", False)]


def test_launch_and_config_folders_are_share_files(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace(
        "ament_package()", "install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\nament_package()")
    folder = cmake_package(tmp_path / "p", "p", text)
    write(folder / "launch" / "circle.launch.py", "")
    write(folder / "config" / "params.yaml", "")
    assert read_package(folder).share == (folder / "launch", folder / "config")


def test_interfaces_listed_and_not_listed(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("ament_package()", (
        'find_package(rosidl_default_generators REQUIRED)\n'
        'rosidl_generate_interfaces(${PROJECT_NAME}\n  "srv/MyNumberGame.srv"\n  DEPENDENCIES builtin_interfaces)\n'
        "ament_package()"))
    folder = cmake_package(tmp_path / "p", "p", text,
                           extra="<member_of_group>rosidl_interface_packages</member_of_group>")
    write(folder / "srv" / "MyNumberGame.srv", "int32 guess\n---\nstring hint\n")
    write(folder / "action" / "ExploreForward.action", "float32 stopping_distance\n---\n---\n")
    package = read_package(folder)
    assert [(i.kind, i.path.name, i.listed) for i in package.interfaces] == [
        ("srv", "MyNumberGame.srv", True), ("action", "ExploreForward.action", False)]
    [finding] = package.findings
    assert "action/ExploreForward.action is not listed in rosidl_generate_interfaces()" in finding


def test_interfaces_need_member_of_group(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace(
        "ament_package()", 'rosidl_generate_interfaces(${PROJECT_NAME} "srv/A.srv")\nament_package()')
    folder = cmake_package(tmp_path / "p", "p", text)
    write(folder / "srv" / "A.srv", "---\n")
    [finding] = read_package(folder).findings
    assert "<member_of_group>rosidl_interface_packages</member_of_group>" in finding


def test_catkin_messages_and_python_setup(tmp_path: Path) -> None:
    folder = tmp_path / "beginner"
    write(folder / "package.xml", MANIFEST.format(name="beginner", buildtool="catkin", build_type="catkin",
                                                   extra="").replace("rclpy", "rospy"))
    write(folder / "CMakeLists.txt", "project(beginner)\nfind_package(catkin REQUIRED)\ncatkin_python_setup()\n"
                                      "add_message_files(FILES Num.msg)\nadd_service_files(DIRECTORY srv)\n"
                                      "generate_messages(DEPENDENCIES std_msgs)\ncatkin_package()\n")
    write(folder / "setup.py", "from catkin_pkg.python_setup import generate_distutils_setup\n"
                                "d = generate_distutils_setup(packages=['beginner_tools'], package_dir={'': 'src'})\n")
    write(folder / "src" / "beginner_tools" / "__init__.py", "")
    write(folder / "msg" / "Num.msg", "int64 num\n")
    write(folder / "msg" / "Other.msg", "int64 num\n")
    write(folder / "srv" / "AddTwoInts.srv", "int64 a\n---\nint64 sum\n")
    package = read_package(folder)
    assert package.build_type == "catkin"
    assert [(p.name, p.root) for p in package.python_packages] == [("beginner_tools", folder / "src")]
    assert [(i.path.name, i.listed) for i in package.interfaces] == [
        ("Num.msg", True), ("Other.msg", False), ("AddTwoInts.srv", True)]
    assert [f for f in package.findings if "add_message_files()" in f and "Other.msg" in f]


@pytest.mark.parametrize("text,words", [
    ("project(p\n", 'Function missing ending ")"'),
    ("project(p)\n" + "set(X y)\n" * 40000, "KiB"),
    ('\xff\xfeproject(p)\n', "Expected a command name"),
])
def test_a_cmakelists_colcon_would_refuse_is_a_finding(tmp_path: Path, text: str, words: str) -> None:
    started = time.monotonic()
    package = read_package(cmake_package(tmp_path / "p", "p", text))
    assert time.monotonic() - started < 2.0
    [finding] = package.findings
    assert words in finding and "colcon build" in finding
    assert package.executables == ()


def test_an_ament_cmake_package_without_cmakelists(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    (folder / "CMakeLists.txt").unlink()
    [finding] = read_package(folder).findings
    assert "no CMakeLists.txt" in finding


def test_a_malformed_package_xml_keeps_its_name(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    (folder / "package.xml").write_text("<package><name>p</name><export></package>\n")
    package = read_package(folder)
    assert package.name == "p"
    assert any("package.xml line 1 is not valid XML" in f for f in package.findings)


def test_a_package_xml_with_entities_is_refused_quickly(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    lol = "".join(f'<!ENTITY l{i} "{"&l%d;" % (i - 1) * 10 if i else "lol"}">' for i in range(10))
    (folder / "package.xml").write_text(f"<?xml version='1.0'?><!DOCTYPE p [{lol}]><package><name>p</name>"
                                        "<description>&l9;</description></package>")
    started = time.monotonic()
    package = read_package(folder)
    assert time.monotonic() - started < 1.0
    assert any("DOCTYPE" in f for f in package.findings)


def test_an_ament_python_package(tmp_path: Path) -> None:
    folder = tmp_path / "pkg"
    write(folder / "package.xml", MANIFEST.format(name="my_pkg", buildtool="ament_python",
                                                   build_type="ament_python", extra=""))
    write(folder / "setup.py", "from setuptools import find_packages, setup\npackage_name = 'my_pkg'\n"
                                "setup(name=package_name, packages=find_packages(exclude=['test']),\n"
                                "      entry_points={'console_scripts': ['circle = my_pkg.move_circle:main']})\n")
    write(folder / "my_pkg" / "__init__.py", "")
    write(folder / "my_pkg" / "move_circle.py", "import rclpy\n")
    write(folder / "test" / "__init__.py", "")
    package = read_package(folder)
    assert package.build_type == "ament_python" and package.setup_package_name == "my_pkg"
    [exe] = package.executables
    assert (exe.name, exe.entry) == ("circle", "my_pkg.move_circle:main")
    assert exe.script == folder / "my_pkg" / "move_circle.py"
    assert [p.name for p in package.python_packages] == ["my_pkg"]


def test_a_setup_py_that_does_not_parse_is_a_finding_and_is_never_run(tmp_path: Path) -> None:
    folder = tmp_path / "pkg"
    marker = tmp_path / "ran"
    write(folder / "package.xml", "<package format='3'><name>my_pkg</name></package>")
    write(folder / "setup.py", f"open({str(marker)!r}, 'w').close()\nsetup(name='my_pkg',\n")
    package = read_package(folder)
    assert package.build_type == "ament_python" and not marker.exists()
    [finding] = package.findings
    assert "setup.py line" in finding and "does not parse" in finding


def test_a_workspace_src_with_several_packages(tmp_path: Path) -> None:
    src = tmp_path / "ros2_ws" / "src"
    cmake_package(src / "part2_navigation")
    cmake_package(src / "team_interfaces", "team_interfaces")
    cmake_package(tmp_path / "ros2_ws" / "build" / "part2_navigation")  # colcon's output is not a package
    cmake_package(src / ".git" / "hidden", "hidden")
    workspace = read_workspace(tmp_path)
    assert workspace.folders == {"part2_navigation": src / "part2_navigation",
                                 "team_interfaces": src / "team_interfaces"}
    assert [p.name for p in workspace.python_packages()] == ["part2_navigation_modules", "team_interfaces_modules"]
    assert find_packages(tmp_path) == workspace.folders


def test_the_shallowest_package_of_a_name_wins(tmp_path: Path) -> None:
    cmake_package(tmp_path / "a" / "b" / "p", "p")
    cmake_package(tmp_path / "z" / "p", "p")
    assert read_workspace(tmp_path).folders == {"p": tmp_path / "z" / "p"}


def test_a_script_s_workspace_is_its_package(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    workspace = read_workspace(folder / "scripts" / "move_circle.py")
    assert workspace.folders == {"p": folder}
    assert workspace.enclosing(folder / "scripts" / "move_circle.py").name == "p"
    assert read_workspace(folder / "scripts").folders == {"p": folder}


def test_ros2_run_finds_what_the_build_installs_with_its_py(tmp_path: Path) -> None:
    workspace = read_workspace(cmake_package(tmp_path / "p", "p"))
    assert workspace.executable("p", "move_circle.py").script == tmp_path / "p" / "scripts" / "move_circle.py"
    with pytest.raises(WorkspaceError, match="No executable found"):
        workspace.executable("p", "move_circle")
    with pytest.raises(WorkspaceError, match="Package 'q' not found"):
        workspace.executable("q", "move_circle.py")


def test_rosrun_finds_any_executable_file_of_a_catkin_package(tmp_path: Path) -> None:
    folder = tmp_path / "beginner"
    write(folder / "package.xml", "<package format='2'><name>beginner</name>"
                                  "<buildtool_depend>catkin</buildtool_depend></package>")
    write(folder / "src" / "mover.py", "import rospy\n").chmod(0o755)
    write(folder / "src" / "plain.py", "import rospy\n").chmod(0o644)
    workspace = read_workspace(tmp_path)
    assert workspace.executable("beginner", "mover.py").script == folder / "src" / "mover.py"
    with pytest.raises(WorkspaceError, match="Couldn't find executable named plain.py"):
        workspace.executable("beginner", "plain.py")


def test_a_malformed_package_xml_of_an_ament_cmake_package_stays_ament_cmake(tmp_path: Path) -> None:
    folder = cmake_package(tmp_path / "p", "p")
    (folder / "package.xml").write_text("<package><name>p</name><export></package>\n")
    assert read_package(folder).build_type == "ament_cmake"


def test_an_interface_listed_but_missing(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace(
        "ament_package()", 'rosidl_generate_interfaces(${PROJECT_NAME} "srv/Gone.srv")\nament_package()')
    folder = cmake_package(tmp_path / "p", "p", text,
                           extra="<member_of_group>rosidl_interface_packages</member_of_group>")
    [finding] = read_package(folder).findings
    assert "line 16" in finding and "the passed file 'srv/Gone.srv' doesn't exist" in finding


def test_a_program_installed_under_another_name(tmp_path: Path) -> None:
    text = TEMPLATE.format(name="p").replace("  DESTINATION", "  RENAME circle\n  DESTINATION")
    workspace = read_workspace(cmake_package(tmp_path / "p", "p", text))
    assert workspace.executable("p", "circle").script.name == "move_circle.py"
