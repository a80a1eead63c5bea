"""A run of an rclpy node that imports the submission's own interfaces: the node builds their classes from START,
publishes a student message, and the recording carries its schema so rosbags decodes it from the file alone."""
from __future__ import annotations

from pathlib import Path

import pytest
from mcap.reader import make_reader
from rosbags.typesys import Stores, get_typestore, get_types_from_msg

from grader.interfaces import run_interfaces
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from grader.workspace import read_workspace
from sim import Scenario

pytestmark = pytest.mark.slow

EXAMPLE = Path(__file__).resolve().parents[2] / "reference_solutions_ros2_cmake"

NODE = """import rclpy
from rclpy.node import Node
from number_game_interfaces.msg import Guess
from number_game_interfaces.srv import MyNumberGame
from number_game_interfaces.action import ExploreForward


class Guesser(Node):
    def __init__(self):
        super().__init__("guesser")
        self.pub = self.create_publisher(Guess, "guesses", 10)
        self.create_timer(0.1, self.tick)
        self.get_logger().info(repr(MyNumberGame.Request(guess=3)) + " " + repr(ExploreForward.Goal()))

    def tick(self):
        msg = Guess(value=42)
        msg.where.x = 1.5
        self.pub.publish(msg)


rclpy.init()
rclpy.spin(Guesser())
"""


def test_a_student_message_is_published_recorded_and_decoded(tmp_path: Path) -> None:
    script = tmp_path / "guesser.py"
    script.write_text(NODE)
    interfaces = run_interfaces(read_workspace(EXAMPLE), "ros2")
    assert interfaces.findings == []
    spec = RunSpec(scenario=Scenario(duration=1.0), nodes=(NodeSpec(script=script, flavour="ros2"),),
                   interfaces=interfaces)
    result = run(spec, tmp_path / "run.mcap", tmp_path / "run.log")
    assert result.nodes[0].status == "stopped_at_end", (tmp_path / "run.log").read_text()[-2000:]
    with open(tmp_path / "run.mcap", "rb") as stream:
        reader = make_reader(stream)
        summary = reader.get_summary()
        schemas = {s.name: s.data.decode() for s in summary.schemas.values()}
        messages = [(channel.topic, message.data) for _, channel, message in reader.iter_messages(topics=["/guesses"])]
    assert "number_game_interfaces/msg/Guess" in schemas
    assert messages, "the node's Guess messages were not recorded"
    # Decoded with nothing but the file's own schema, as Foxglove or another reader would.
    store = get_typestore(Stores.EMPTY)
    store.register(get_types_from_msg(schemas["number_game_interfaces/msg/Guess"], "number_game_interfaces/msg/Guess"))
    decoded = store.deserialize_cdr(messages[0][1], "number_game_interfaces/msg/Guess")
    assert (decoded.value, decoded.where.x, decoded.name, list(decoded.weights)) == (42, 1.5, "anonymous",
                                                                                   [0.5, 0.25, 0.25])
    log = (tmp_path / "run.log").read_text()
    assert "number_game_interfaces.srv.MyNumberGame_Request(guess=3, cheat=False)" in log
