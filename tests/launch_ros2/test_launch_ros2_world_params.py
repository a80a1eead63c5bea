"""Parameters a ROS 2 launch file gives turtlesim_node (dicts, YAML files, -p) start the world's node with them, as
rcl reads that node's command line: the background is the launch file's from the first picture; Jazzy's turtlesim
ignores an override it does not declare."""
from __future__ import annotations

from grader.launch.ros2_acts import launch_acts, with_acts, world_params
from sim import Scenario
from sim.worlds import open_world


def _turtlesim(args: list[str], contents: list[str], name: str = "turtlesim", namespace: str = "") -> dict:
    return {"kind": "node", "world": True, "package": "turtlesim", "executable": "turtlesim_node", "node_name": name,
            "namespace": namespace, "args": ["--ros-args", *args],
            "params_files": [{"content": text} for text in contents]}


def test_dicts_files_and_p_are_read_in_order_for_the_nodes_name() -> None:
    process = _turtlesim(["--params-file", "/tmp/a", "-p", "background_g:=7", "--params-file", "/tmp/b"],
                         ["/**:\n  ros__parameters:\n    background_r: 255\n    background_g: 1\n",
                          "sim:\n  ros__parameters:\n    background_b: 0\nother:\n  ros__parameters:\n    holonomic: true\n"],
                         name="sim")
    assert world_params(process) == {"background_r": 255, "background_g": 7, "background_b": 0}


def test_the_world_starts_with_the_launch_files_background_and_ignores_what_jazzy_does_not_declare() -> None:
    acts, findings, _ = launch_acts([_turtlesim(["--params-file", "/tmp/a"], [
        "/**:\n  ros__parameters:\n    background_r: 255\n    holonomic: true\n    colour: 3\n"])], "t.launch.py")
    assert findings == [] and acts.world_params == {"background_r": 255, "holonomic": True, "colour": 3}
    scenario = with_acts(Scenario(robot="turtlesim", duration=1.0), acts)
    for flavour, expected in (("ros2", {"background_r": 255, "holonomic": True}),
                              ("ros1", {"background_r": 255, "holonomic": True, "colour": 3})):
        world = open_world(scenario, flavour)
        tree: dict[str, object] = {}

        class Params:
            def has(self, name: str) -> bool:
                return name in tree

            def get(self, name: str, default: object = None) -> object:
                return tree.get(name, default)

            def set(self, name: str, value: object) -> None:
                tree[name] = value

        world.use_parameters(Params())
        assert {k.removeprefix("/turtlesim/"): v for k, v in tree.items()
                if k.removeprefix("/turtlesim/") in expected} == expected
        assert ("/turtlesim/colour" in tree) == (flavour == "ros1")
        assert world.canvas.background == (255, 86, 255)


def test_a_parameter_file_rcl_refuses_is_a_finding() -> None:
    _, findings, _ = launch_acts([_turtlesim(["--params-file", "/tmp/a"], ["/**:\n  background_r: 255\n"])],
                                 "t.launch.py")
    assert len(findings) == 1 and findings[0].startswith("t.launch.py gives turtlesim_node parameters rcl refuses: ")
