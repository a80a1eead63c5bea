"""A run of an rclpy node that imports the submission's own interfaces: the node builds their classes from START,
publishes a student message, and the recording carries its schema so rosbags decodes it from the file alone."""
from __future__ import annotations

from pathlib import Path

import pytest
from mcap.reader import make_reader
from rosbags.typesys import Stores, get_typestore, get_types_from_msg

from grader.interfaces import run_interfaces
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from grader.workspace import read_workspace
from sim import Scenario
from sim.scenario import ServiceCallSpec

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


SERVER = """import rclpy
from rclpy.node import Node
from number_game_interfaces.srv import MyNumberGame


class Game(Node):
    def __init__(self):
        super().__init__("number_game")
        self.guesses = 0
        self.create_service(MyNumberGame, "guess_the_number", self.answer)

    def answer(self, request, response):
        self.guesses += 1
        response.num_guesses = self.guesses
        response.correct = request.guess == 7
        response.hint = "Correct" if response.correct else ("Higher" if request.guess < 7 else "Lower")
        return response


rclpy.init()
rclpy.spin(Game())
"""


def test_the_grader_calls_a_student_service_of_the_student_s_type(tmp_path: Path) -> None:
    script = tmp_path / "number_game.py"
    script.write_text(SERVER)
    calls = [ServiceCallSpec(t=0.5, service="/guess_the_number", type="number_game_interfaces/srv/MyNumberGame",
                             request={"guess": g, "cheat": False}) for g in (3, 7)]
    spec = RunSpec(scenario=Scenario(duration=1.5, service_calls=calls),
                   nodes=(NodeSpec(script=script, flavour="ros2"),),
                   interfaces=run_interfaces(read_workspace(EXAMPLE), "ros2"))
    result = run(spec, tmp_path / "run.mcap", tmp_path / "run.log")
    assert result.nodes[0].status == "stopped_at_end", (tmp_path / "run.log").read_text()[-2000:]
    recording = Recording.open(tmp_path / "run.mcap")
    responses = [(m.num_guesses, m.hint, m.correct)
                 for _, m in recording.messages("/rosgrade/service/guess_the_number/response")]
    assert responses == [(1, "Higher", False), (2, "Correct", True)]


ROSPY_NODE = """#!/usr/bin/env python3
import rospy
from game_msgs.msg import Tag
from game_msgs.srv import MyNumberGameRequest

rospy.init_node("tagger")
pub = rospy.Publisher("tags", Tag, queue_size=1)
rospy.loginfo(str(MyNumberGameRequest(guess=4)).replace("\\n", " "))
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    pub.publish(Tag(name="seven"))
    rate.sleep()
"""


def test_a_rospy_node_publishes_a_student_message(tmp_path: Path) -> None:
    script = tmp_path / "tagger.py"
    script.write_text(ROSPY_NODE)
    spec = RunSpec(scenario=Scenario(duration=1.0), nodes=(NodeSpec(script=script),),
                   interfaces=run_interfaces(read_workspace(Path(__file__).parent / "game_msgs"), "ros1"))
    result = run(spec, tmp_path / "run.mcap", tmp_path / "run.log")
    assert result.nodes[0].status == "stopped_at_end", (tmp_path / "run.log").read_text()[-2000:]
    recording = Recording.open(tmp_path / "run.mcap")
    names = [m.name for _, m in recording.messages("/tags")]
    assert names and set(names) == {"seven"}
    assert "guess: 4 cheat: False" in (tmp_path / "run.log").read_text()
