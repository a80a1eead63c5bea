"""Reading a workspace's interface files: what each file defines and is named, defaults, what the build leaves out,
ROS 1 and ROS 2 spellings, and the catalog and node payload made from them."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from grader.interfaces import catalog_for
from grader.interfaces.defaults import field_defaults
from grader.recording import Recorder, Recording
from rosbags.typesys import get_types_from_msg
from tests.interfaces.workspaces import interfaces, package

SRV = "int32 guess\nbool cheat\n---\nint32 num_guesses\nstring hint\nbool correct\n"
ACTION = "float32 fwd_velocity\n---\nfloat32 total\n---\nfloat32 current\n"


def test_ros2_names_of_a_service_and_an_action(tmp_path: Path) -> None:
    package(tmp_path, "game_interfaces", {"srv/MyNumberGame.srv": SRV, "action/ExploreForward.action": ACTION})
    found = interfaces(tmp_path)
    assert found.services == {"game_interfaces/srv/MyNumberGame": ("game_interfaces/srv/MyNumberGame_Request",
                                                                    "game_interfaces/srv/MyNumberGame_Response")}
    assert found.actions == {"game_interfaces/action/ExploreForward": tuple(
        f"game_interfaces/action/ExploreForward_{p}" for p in ("Goal", "Result", "Feedback"))}
    catalog = catalog_for("ros2", found)
    assert catalog.known_service("game_interfaces/srv/MyNumberGame")
    assert catalog.known_service("game_interfaces/action/ExploreForward_SendGoal")
    assert catalog.service_part("game_interfaces/action/ExploreForward_GetResult", "Response") == \
        "game_interfaces/action/ExploreForward_GetResult_Response"
    assert "int8 status" in catalog.definition("game_interfaces/action/ExploreForward_GetResult_Response")
    assert set(found.payload["services"]) == {"game_interfaces/srv/MyNumberGame",
                                              "game_interfaces/action/ExploreForward_SendGoal",
                                              "game_interfaces/action/ExploreForward_GetResult"}
    # the node is given the action's own types, and not those its built-in table has (the goal's UUID included)
    assert "game_interfaces/action/ExploreForward_FeedbackMessage" in found.payload["messages"]
    assert "unique_identifier_msgs/msg/UUID" not in found.payload["messages"]
    assert "builtin_interfaces/msg/Time" not in found.payload["messages"]


def test_request_bytes_round_trip_through_the_run_catalog(tmp_path: Path) -> None:
    package(tmp_path, "game_interfaces", {"srv/MyNumberGame.srv": SRV})
    catalog = catalog_for("ros2", interfaces(tmp_path))
    part = catalog.service_part("game_interfaces/srv/MyNumberGame", "Request")
    data = catalog.encode(part, catalog.message_class(part)(guess=-4, cheat=True))
    assert (catalog.decode(part, data).guess, catalog.decode(part, data).cheat) == (-4, True)


def test_ros1_names(tmp_path: Path) -> None:
    package(tmp_path, "game_msgs", {"srv/MyNumberGame.srv": SRV, "msg/Tag.msg": "string name\n"}, flavour="ros1")
    found = interfaces(tmp_path, "ros1")
    assert sorted(found.types) == ["game_msgs/msg/MyNumberGameRequest", "game_msgs/msg/MyNumberGameResponse",
                                   "game_msgs/msg/Tag"]
    catalog = catalog_for("ros1", found)
    assert catalog.known("game_msgs/Tag") and catalog.known_service("game_msgs/MyNumberGame")
    assert found.payload == {"messages": {"game_msgs/Tag": "string name\n"},
                             "services": {"game_msgs/MyNumberGame": SRV.replace("---\n", "---\n")}}


def test_only_what_the_build_generates_and_only_for_its_ros_version(tmp_path: Path) -> None:
    folder = package(tmp_path, "a_interfaces", {"msg/Listed.msg": "int32 x\n"})
    (folder / "msg" / "Unlisted.msg").write_text("int32 y\n")
    package(tmp_path, "b_msgs", {"msg/Catkin.msg": "int32 z\n"}, flavour="ros1")
    assert list(interfaces(tmp_path, "ros2").types) == ["a_interfaces/msg/Listed"]
    assert list(interfaces(tmp_path, "ros1").types) == ["b_msgs/msg/Catkin"]


def test_a_type_from_a_sibling_package(tmp_path: Path) -> None:
    package(tmp_path, "base_interfaces", {"msg/Tag.msg": "string name\n"})
    package(tmp_path, "game_interfaces", {"msg/Guess.msg": "base_interfaces/Tag tag\nTagged local\n",
                                          "msg/Tagged.msg": "base_interfaces/Tag[<=3] tags\n"})
    found = interfaces(tmp_path)
    assert found.findings == []
    assert found.types["game_interfaces/msg/Guess"][1][1][1][1] == "game_interfaces/msg/Tagged"


def test_field_defaults() -> None:
    text = ('int32 A=1\nint32 B = 2\nint32 retries 3 # three\nbool on true\nfloat64 gain 0.5\n'
            'string name "a # b"\nstring bare hello\nint8[] seq [1, -2]\nint32 none\n')
    typedef = get_types_from_msg(text, "p/msg/D")["p/msg/D"]
    assert field_defaults(text, typedef) == {"retries": 3, "on": True, "gain": 0.5, "name": "a # b",
                                             "bare": "hello", "seq": [1, -2]}


def test_an_action_s_messages_are_recorded_and_read_back(tmp_path: Path) -> None:
    """The schema of a type holding an action's part names it in full; `rosgrade score`'s reader decodes it."""
    package(tmp_path, "game_interfaces", {"action/ExploreForward.action": ACTION, "srv/MyNumberGame.srv": SRV})
    catalog = catalog_for("ros2", interfaces(tmp_path))
    feedback = "game_interfaces/action/ExploreForward_FeedbackMessage"
    assert "game_interfaces/action/ExploreForward_Feedback feedback" in catalog.definition(feedback)
    cls = catalog.message_class(feedback)
    uuid = catalog.message_class("unique_identifier_msgs/msg/UUID")(uuid=np.arange(16, dtype=np.uint8))
    message = cls(goal_id=uuid, feedback=catalog.message_class("game_interfaces/action/ExploreForward_Feedback")(
        current=np.float32(2.5)))
    request_type = catalog.service_part("game_interfaces/srv/MyNumberGame", "Request")
    request = catalog.message_class(request_type)(guess=9, cheat=False)
    path = tmp_path / "run.mcap"
    with Recorder(path, metadata={}, catalog=catalog) as recorder:
        recorder.write("/explore/_action/feedback", feedback, catalog.encode(feedback, message), 5, callerid="/n",
                       origin="node")
        recorder.write("/rosgrade/service/guess/request", request_type, catalog.encode(request_type, request), 6,
                       callerid="/n", origin="node")
    recording = Recording.open(path)
    ((_, read),) = list(recording.messages("/explore/_action/feedback"))
    assert (read.feedback.current, list(read.goal_id.uuid)) == (2.5, list(range(16)))
    ((_, read),) = list(recording.messages("/rosgrade/service/guess/request"))
    assert read.guess == 9
