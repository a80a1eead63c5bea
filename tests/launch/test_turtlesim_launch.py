"""turtlesim from a launch file: ``turtlesim_node`` is the turtlesim world (its ns and remaps honoured by bridging
remaps), ``turtle_teleop_key`` is the grader's node with the semantics of noetic's teleop_turtle_key.cpp, and a
world that does not fit the task's robot is refused with the file and line."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_task
from grader.launch import LaunchError, find_packages, read_launch, turtlesim
from grader.launch.specs import node_specs
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.runtime import RunSpec
from grader.runtime.session import run
from sim import Scenario

WORKSPACE = Path(__file__).parent / "ws" / "src"
CASES = WORKSPACE / "turtle_cases" / "launch"
REFERENCE = Path(__file__).resolve().parents[2] / "reference_solutions_turtlesim"
UP, DOWN, RIGHT, LEFT = "\x1b[A", "\x1b[B", "\x1b[C", "\x1b[D"


def _launch(path: Path, args: dict[str, str] | None = None):
    packages = find_packages(path.parents[2])
    return read_launch(path, args or {}, packages), packages


def _specs(path: Path, args: dict[str, str] | None = None, stdin: str | None = None):
    launch, packages = _launch(path, args)
    return node_specs(launch, packages, stdin)


def _write(tmp_path: Path, body: str) -> Path:
    package = tmp_path / "src" / "turtle_cases"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text((WORKSPACE / "turtle_cases" / "package.xml").read_text())
    path = package / "launch" / "case.launch"
    path.write_text(f"<launch>\n{body}\n</launch>\n")
    return path


# -- mapping -----------------------------------------------------------------------------------------------------

def test_turtlesim_node_is_the_world_and_teleop_is_the_graders_node():
    launch_file = REFERENCE / "lab2_turtlesim" / "launch" / "teleopturtlesim4.launch"
    nodes, notes = _specs(launch_file, {"teleop": "1"}, stdin=UP)
    assert [(n.script, n.args, n.ros_namespace, n.stdin) for n in nodes] == [
        (turtlesim.TELEOP_SCRIPT, ("__name:=teleop_key",), None, UP)]
    launch, _ = _launch(launch_file, {"teleop": "1"})
    assert notes == [] and turtlesim.check_robot(launch, turtlesim.world_node(launch), "turtlesim") == []


def test_teleop_zero_starts_the_students_node_instead():
    nodes, _ = _specs(REFERENCE / "lab2_turtlesim" / "launch" / "teleopturtlesim4.launch", {"teleop": "0"})
    assert [n.script.name for n in nodes] == ["pubvel.py"]


def test_a_namespaced_turtlesim_is_reached_through_bridging_remaps():
    nodes, notes = _specs(WORKSPACE / "launch_cases" / "launch" / "turtlesim.launch", {"teleop": "1"})
    (teleop,) = nodes
    assert teleop.ros_namespace == "/sim" and teleop.params["/sim/scale_linear"] == 1.5
    remaps = dict(arg.split(":=") for arg in teleop.args if not arg.startswith("__"))
    assert remaps["/sim/turtle1/cmd_vel"] == "/turtle1/cmd_vel"
    assert remaps["/sim/pose"] == "/turtle1/pose"  # turtlesim_node's own <remap from="turtle1/pose" to="pose"/>
    assert remaps["/sim/spawn"] == "/spawn"
    # What the launched turtlesim does not serve reaches nothing, as with roslaunch.
    assert remaps["/turtle1/cmd_vel"] == turtlesim.UNSERVED + "/turtle1/cmd_vel"
    assert remaps["/spawn"] == turtlesim.UNSERVED + "/spawn"
    assert "/sim/turtle1/pose" not in remaps  # nothing serves it there: the remap moved it
    launch, _ = _launch(WORKSPACE / "launch_cases" / "launch" / "turtlesim.launch", {"teleop": "1"})
    found = turtlesim.check_robot(launch, turtlesim.world_node(launch), "turtlesim")
    assert any("turtlesim.launch line 5: turtlesim_node runs as /sim/turtlesim" in n and "/sim/pose" in n
               for n in found)
    assert any("runs as /turtlesim: it starts with /sim/turtlesim/background_r as its own parameters" in n
               for n in found)


def test_a_nodes_own_remap_onto_turtlesims_name_is_bridged_to_its_end(tmp_path):
    path = _write(tmp_path, '<node pkg="turtlesim" type="turtlesim_node" name="sim" ns="sim"/>\n'
                            '<node pkg="turtlesim" type="turtle_teleop_key" name="teleop">\n'
                            '  <remap from="turtle1/cmd_vel" to="/sim/turtle1/cmd_vel"/>\n</node>')
    (teleop,), _ = _specs(path)
    assert teleop.args[0] == "turtle1/cmd_vel:=/turtle1/cmd_vel"  # rospy applies one remap: the target is bridged
    assert "/turtle1/cmd_vel:=/no_turtlesim_here/turtle1/cmd_vel" not in teleop.args  # its own remap comes first


def test_turtlesim_in_the_root_namespace_adds_no_remaps():
    (teleop,), _ = _specs(CASES / "keys.launch")
    assert teleop.args == ("__name:=teleop",)


def test_the_roslaunch_tutorials_two_turtlesims_are_two_windows(tmp_path):
    mimic_launch = _write(tmp_path, '<group ns="turtlesim1"><node pkg="turtlesim" name="sim" type="turtlesim_node"/>'
                                    '</group>\n<group ns="turtlesim2"><node pkg="turtlesim" name="sim" '
                                    'type="turtlesim_node"/></group>\n<node pkg="turtlesim" name="mimic" type="mimic">'
                                    '<remap from="input" to="turtlesim1/turtle1"/>'
                                    '<remap from="output" to="turtlesim2/turtle1"/></node>')
    launch = read_launch(mimic_launch, {}, {}, confine_to=tmp_path)
    world = turtlesim.world_node(launch)
    assert world.node.full_name == "/turtlesim1/sim" and [w.node for w in world.windows] == ["/turtlesim2/sim"]
    assert world.world_names["/turtlesim1/turtle1/cmd_vel"] == "/turtle1/cmd_vel"
    assert world.world_names["/turtlesim1/sim"] == "/turtlesim"
    assert "/turtlesim2/turtle1/cmd_vel" not in world.world_names  # the second window keeps its own names
    (mimic,), notes = _specs(mimic_launch)
    assert mimic.script.name == "turtle_mimic.py"
    assert any("a second turtlesim window, /turtlesim2/sim" in note for note in
               turtlesim.check_robot(launch, world, "turtlesim"))


# -- refusals ----------------------------------------------------------------------------------------------------

@pytest.mark.parametrize(("body", "says"), [
    ('<node pkg="turtlesim" type="turtlesim_node" name="a"/>\n<node pkg="turtlesim" type="turtlesim_node" name="b"/>',
     "case.launch line 3: this turtlesim_node would share its topics and services with the one at case.launch line "
     "2: start each turtlesim in a namespace of its own"),
    ('<node pkg="turtlesim" type="turtlesim_node" name="a"/>\n<group ns="t2"><node pkg="turtlesim" '
     'type="turtlesim_node" name="b"><remap from="turtle1/pose" to="/p"/></node></group>',
     "case.launch line 3: the grader runs a second turtlesim window under the names of its namespace only"),
    ('<node pkg="turtlesim" type="turtlesim_node" name="a"/>\n<group ns="2nd"><node pkg="turtlesim" '
     'type="turtlesim_node" name="b"/></group>', "case.launch line 3: turtlesim_node /2nd/b is not a valid ROS node name"),
    ('<node pkg="turtlesim" type="turtlesim_node" name="a"><remap from="turtle1/pose" to="turtle1/cmd_vel"/></node>',
     "case.launch line 2: the remaps of turtlesim_node give two of its topics or services the same name"),
    ('<node pkg="turtlesim" type="turtlesim_node" name="a"/>',
     "case.launch starts only turtlesim_node (case.launch line 2): add a <node> for your script"),
    ('<node pkg="turtlesim" type="draw_square" name="square"/>',
     'case.launch line 2: node square: type="draw_square" is not a node of turtlesim the grader provides'),
])
def test_what_cannot_be_honoured_is_refused_with_file_and_line(tmp_path, body, says):
    with pytest.raises(LaunchError) as caught:
        _specs(_write(tmp_path, body))
    assert says in str(caught.value)


def test_find_turtlesim_says_how_to_start_its_nodes(tmp_path):
    path = _write(tmp_path, '<include file="$(find turtlesim)/launch/x.launch"/>')
    with pytest.raises(LaunchError, match=r'case.launch line 2: .*package turtlesim has no files in the grader; '
                                          r'start its nodes with <node pkg="turtlesim" type=...>'):
        _launch(path)


def test_turtlesim_node_in_a_turtlebot_task_is_refused(tmp_path):
    path = _write(tmp_path, '<node pkg="turtlesim" type="turtlesim_node" name="sim"/>\n'
                            '<node pkg="turtlesim" type="turtle_teleop_key" name="teleop"/>')
    path.rename(path.with_name("move_turtlebot.launch"))
    report = grade_task(tmp_path, load_rubrics()["move_distance_launch"], tmp_path / "out")
    assert report.status == "error"
    assert "move_turtlebot.launch line 2: the launch file starts turtlesim_node, but this task is graded on a " \
           "turtlebot3_waffle, not on turtlesim" in report.message


def test_a_gazebo_world_in_a_turtlesim_task_is_refused(tmp_path):
    path = _write(tmp_path, '<include file="$(find turtlebot3_gazebo)/launch/turtlebot3_empty_world.launch"/>\n'
                            '<node pkg="turtlesim" type="turtle_teleop_key" name="teleop"/>')
    launch, _ = _launch(path)
    with pytest.raises(LaunchError, match="case.launch line 2: turtlebot3_gazebo/launch/turtlebot3_empty_world.launch "
                                          "starts Gazebo with a turtlebot3_waffle, but this task is graded on "
                                          "turtlesim"):
        turtlesim.check_robot(launch, turtlesim.world_node(launch), "turtlesim")


def test_a_turtlesim_task_whose_launch_file_starts_no_turtlesim_is_told(tmp_path):
    launch, _ = _launch(_write(tmp_path, '<node pkg="turtlesim" type="turtle_teleop_key" name="teleop"/>'))
    (note,) = turtlesim.check_robot(launch, None, "turtlesim")
    assert "case.launch starts no turtlesim_node" in note


# -- runs (the grader's teleop node, namespaces, services) --------------------------------------------------------

def _run(tmp_path: Path, launch_file: Path, stdin: str | None, duration: float = 4.0):
    nodes, _ = _specs(launch_file, stdin=stdin)
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=duration), nodes=nodes)
    result = run(spec, tmp_path / "run.mcap", tmp_path / "run.log")
    return result, Recording.open(tmp_path / "run.mcap")


def _expected_twists(keys: str, scale_linear: float, scale_angular: float) -> list[tuple[float, float]]:
    """teleop_turtle_key.cpp read byte by byte: A/B/C/D (an arrow's last byte) publish, q ends, the rest nothing."""
    out = []
    for byte in keys:
        if byte == "q":
            break
        step = {"A": (1.0, 0.0), "B": (-1.0, 0.0), "C": (0.0, -1.0), "D": (0.0, 1.0)}.get(byte)
        if step is not None:
            out.append((scale_linear * step[0], scale_angular * step[1]))
    return out


@pytest.mark.slow
def test_teleop_publishes_one_twist_per_arrow_key_with_the_real_scales_until_q(tmp_path):
    keys = UP + DOWN + RIGHT + LEFT + "x A\n" + "q" + UP
    result, recording = _run(tmp_path, CASES / "keys.launch", keys)
    twists = [(m.linear.x, m.angular.z) for _, m in recording.messages("/turtle1/cmd_vel")]
    # scale_linear 1.5 from the global <param>; the private ~scale_angular is not what the C++ node reads: 2.0.
    assert twists == _expected_twists(keys, 1.5, 2.0) == [(1.5, 0.0), (-1.5, 0.0), (0.0, -2.0), (0.0, 2.0),
                                                          (1.5, 0.0)]
    assert [(n.name, n.status, n.exit_code) for n in result.nodes] == [("/teleop", "exited", 0)]
    text = [m.data for _, m in recording.messages("/rosgrade/stdout")]
    assert text[-1] == "Use arrow keys to move the turtle. 'q' to quit."


@pytest.mark.slow
def test_teleop_without_keys_publishes_nothing_and_waits(tmp_path):
    result, recording = _run(tmp_path, CASES / "keys.launch", "", duration=3.0)
    assert list(recording.messages("/turtle1/cmd_vel")) == []
    assert [n.status for n in result.nodes] == ["stopped_at_end"]


@pytest.mark.slow
@pytest.mark.parametrize(("case", "moved"), [("ns_same.launch", True), ("ns_apart.launch", False)])
def test_teleop_reaches_a_namespaced_turtlesim_only_from_its_namespace(tmp_path, case, moved):
    _, recording = _run(tmp_path, CASES / case, UP)
    poses = [m for _, m in recording.messages("/turtle1/pose")]
    travelled = poses[-1].x - poses[0].x
    # One up arrow: 2.0 m/s in 16 ms updates until turtlesim's 1 s timeout drops it (62 updates).
    assert travelled == pytest.approx(2.0 * 0.016 * 62, abs=1e-5) if moved else travelled == 0.0


@pytest.mark.slow
def test_services_of_a_namespaced_turtlesim_are_served(tmp_path):
    _, recording = _run(tmp_path, CASES / "ns_service.launch", None, duration=3.0)
    last = [m for _, m in recording.messages("/turtle1/pose")][-1]
    assert (last.x, last.y) == pytest.approx((2.0, 3.0))
