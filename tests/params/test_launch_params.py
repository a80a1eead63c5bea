"""A launch file's <param> inside turtlesim_node reaches the world before it starts, as roslaunch sets it; a
turtlesim_node under another name has them copied where the world reads them, and the student is told so."""
from __future__ import annotations

from pathlib import Path

from grader.launch import find_packages, read_launch, turtlesim
from grader.launch.specs import node_specs

LAUNCH_WS = Path(__file__).resolve().parents[1] / "launch" / "ws" / "src"


def _write(tmp_path: Path, body: str) -> Path:
    package = tmp_path / "src" / "turtle_cases"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text((LAUNCH_WS / "turtle_cases" / "package.xml").read_text())
    path = package / "launch" / "case.launch"
    path.write_text(f"<launch>\n{body}\n</launch>\n")
    return path


def _read(path: Path):
    packages = find_packages(path.parents[2])
    launch = read_launch(path, {}, packages)
    specs, _ = node_specs(launch, packages)
    return launch, specs, turtlesim.check_robot(launch, turtlesim.world_node(launch), "turtlesim")


TELEOP = '<node pkg="turtlesim" type="turtle_teleop_key" name="teleop"/>'


def test_params_of_a_turtlesim_named_turtlesim_are_the_worlds_own(tmp_path: Path) -> None:
    path = _write(tmp_path, '<node pkg="turtlesim" type="turtlesim_node" name="turtlesim">\n'
                            '  <param name="background_r" value="255"/>\n</node>\n' + TELEOP)
    launch, (teleop,), notes = _read(path)
    assert teleop.params["/turtlesim/background_r"] == 255
    assert turtlesim.world_params(launch, turtlesim.world_node(launch)) == {}
    assert not [n for n in notes if "background" in n]


def test_params_of_a_turtlesim_under_another_name_are_copied_where_the_world_reads_them(tmp_path: Path) -> None:
    path = _write(tmp_path, '<group ns="sim">\n<node pkg="turtlesim" type="turtlesim_node" name="window">\n'
                            '  <param name="background_g" value="0"/>\n  <param name="~background_b" value="9"/>\n'
                            '</node>\n</group>\n<param name="/sim/windowed" value="1"/>\n' + TELEOP)
    launch, (teleop,), notes = _read(path)
    assert turtlesim.world_params(launch, turtlesim.world_node(launch)) == {
        "/turtlesim/background_b": 9, "/turtlesim/background_g": 0}
    # as roslaunch sets them, and where the grader's turtlesim reads them; /sim/windowed is not the node's
    assert teleop.params["/sim/window/background_g"] == 0 and teleop.params["/turtlesim/background_g"] == 0
    assert "/turtlesim/windowed" not in teleop.params
    (note,) = [n for n in notes if "background" in n]
    assert "runs as /turtlesim" in note and "/sim/window/background_b, /sim/window/background_g" in note


def test_a_launch_without_turtlesim_node_adds_nothing(tmp_path: Path) -> None:
    launch, _, _ = _read(_write(tmp_path, TELEOP))
    assert turtlesim.world_params(launch, turtlesim.world_node(launch)) == {}
