"""What a node sends on its channel cannot crash, hang or fool the grader: bad frames, a full pipe, endless
endpoints, a borrowed identity, a fake world. Each ends as a node verdict while the run goes on."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from adversarial_helpers import LIMITS, assert_nothing_escaped, run_case  # noqa: E402

from grader.metrics.run import RunData  # noqa: E402
from grader.recording import Recorder, Recording, twist_bytes  # noqa: E402
from sim import Scenario  # noqa: E402

SCENARIO_END_S = Scenario(duration=8.0).end_ns / 1e9  # run_case's default scenario


@pytest.fixture(autouse=True)
def _no_leftovers():
    yield
    assert_nothing_escaped()


def _world_ran_to_the_end(case) -> None:
    recording = Recording.open(case.folder / "run.mcap")
    assert recording.odometry().t[-1] >= SCENARIO_END_S - 0.1
    assert case.result.ended_s == pytest.approx(SCENARIO_END_S)


# -- every frame field is validated: a bad frame is a verdict for that node, the run goes on ------------------------
@pytest.mark.parametrize("attack, says", [
    ("nested_json", "LOG"),
    ("log_line_not_a_number", "line"),
    ("exception_frames_not_a_list", "frames"),
    ("exception_frame_fields", "frames"),
    ("unknown_kind", "unexpected frame kind 99"),
    ("oversize_json", "exceeds"),
    ("advertise_bad_fields", "queue_size"),
    ("wait_float", "wake_ns"),
    ("output_bad_stream", "stream"),
])
def test_malformed_frame_is_a_protocol_violation(tmp_path, attack, says):
    case = run_case("bad_frame", tmp_path, args=(attack,))
    assert case.node.status == "protocol_violation", case.node.message
    assert case.node.message.startswith("the node broke the grader's channel: ")
    assert says in case.node.message
    assert len(case.node.message) < 400  # one line a student can read, not the frame echoed back
    _world_ran_to_the_end(case)


@pytest.mark.parametrize("attack, says", [
    ("no_moment", "without saying first which moment"),
    ("moment_out_of_range", "outside its batch"),
    ("moment_twice", "not after the moment before it"),
])
def test_a_node_that_lies_about_its_moments_is_a_protocol_violation(tmp_path, attack, says):
    """After a batch of moments the world has run ahead: a node that does not say where it stopped, or names a
    moment the batch did not have, is stopped, and the world still runs to the end from a moment it had."""
    case = run_case("lie_about_moments", tmp_path, args=(attack,))
    assert case.node.status == "protocol_violation", case.node.message
    assert says in case.node.message
    _world_ran_to_the_end(case)


# -- writes to a node never block the grader --------------------------------------------------------------------------
def test_node_that_stops_reading_its_channel_is_stopped_by_its_watchdog(tmp_path):
    case = run_case("stop_reading", tmp_path)
    assert case.node.status == "timeout", case.node.message
    assert "did not read" in case.node.message
    assert case.result.wall_s < LIMITS.wall_s
    _world_ran_to_the_end(case)


# -- endpoints are capped per node and summarised ---------------------------------------------------------------------
def test_endpoint_flood_is_capped_and_summarised(tmp_path):
    case = run_case("endpoint_flood", tmp_path)
    assert case.node.status == "killed_by_limit", case.node.message
    assert "publishers and subscribers" in case.node.message
    assert len(case.result.topics) <= 25
    assert any("more" in line for line in case.result.topics)
    assert len(case.result.diagnostics) <= 25
    _world_ran_to_the_end(case)


# -- identity belongs to the grader -----------------------------------------------------------------------------------
def test_second_init_under_the_drivers_name_is_refused(tmp_path):
    case = run_case("rename_driver", tmp_path)
    assert case.node.status == "protocol_violation", case.node.message
    assert "/rosgrade_driver" in case.node.message and "/mover" in case.node.message
    assert case.node.name == "/mover"
    recording = Recording.open(case.folder / "run.mcap")
    assert all(c != "/rosgrade_driver" for c in recording.commands().callerid)


def test_scoring_tells_driver_from_node_by_origin_not_by_name(tmp_path):
    path = tmp_path / "forged.mcap"
    with Recorder(path, {"rosgrade": {"command_topics": '["/cmd_vel"]'}}) as rec:
        rec.write("/cmd_vel", "geometry_msgs/Twist", twist_bytes((0.1, 0, 0), (0, 0, 0)), 1_000_000_000,
                  callerid="/rosgrade_driver", origin="grader")
        rec.write("/cmd_vel", "geometry_msgs/Twist", twist_bytes((5.0, 0, 0), (0, 0, 0)), 2_000_000_000,
                  callerid="/rosgrade_driver", origin="node")  # a node that named itself like the driver
        rec.write("/odom", "nav_msgs/Odometry", _odometry_bytes(), 2_000_000_000, callerid="/gazebo", origin="world")
    commands = RunData.from_recording(Recording.open(path)).commands
    assert list(commands.linear[:, 0]) == [5.0]


def _odometry_bytes() -> bytes:
    from grader.recording import odometry_bytes
    from sim import OdometrySample
    sample = OdometrySample(t_ns=2_000_000_000, topic="/odom", frame_id="odom", child_frame_id="base_footprint",
                            position=(0.0, 0.0, 0.0), orientation=(0.0, 0.0, 0.0, 1.0), linear=(0.0, 0.0, 0.0),
                            angular=(0.0, 0.0, 0.0), pose_covariance=(0.0,) * 36, twist_covariance=(0.0,) * 36)
    return odometry_bytes(sample, 0)


@pytest.mark.parametrize("name", ["gazebo", "rosgrade_driver", "rosout"])
def test_reserved_names_are_refused(tmp_path, name):
    case = run_case("impersonate_world", tmp_path, args=(name,))
    assert case.node.status == "protocol_violation", case.node.message
    assert f"/{name}" in case.node.message and "reserved" in case.node.message
    recording = Recording.open(case.folder / "run.mcap")
    assert {t.callerid for t in recording.topics() if t.topic == "/tf"} == {"/gazebo"}
    _world_ran_to_the_end(case)


# -- the world's channels are kept apart from the nodes' --------------------------------------------------------------
def test_fake_world_topics_are_recorded_apart_and_never_scored(tmp_path):
    case = run_case("impersonate_world", tmp_path, args=("gazebo_helper",))
    assert case.node.status in ("exited", "killed_after_shutdown"), case.node.message
    recording = Recording.open(case.folder / "run.mcap")
    # The robot stands still at the origin; the node claims x = 9 m everywhere it can.
    assert abs(recording.odometry().x).max() < 0.01
    assert abs(recording.ground_truth().x).max() < 0.01
    origins = {(t.topic, t.callerid): t.origin for t in recording.topics()}
    assert origins[("/odom", "/gazebo")] == "world"
    assert origins[("/ground_truth/odom", "/gazebo")] == "world"
    assert origins[("/tf", "/gazebo")] == "world"
    assert origins[("/tf", "/gazebo_helper")] == "node"
    assert origins[("/tf_static", "/gazebo_helper")] == "node"
    assert origins[("/odom\u200b", "/gazebo_helper")] == "node"
    assert {callerid for (_, callerid), origin in origins.items() if origin == "world"} == {"/gazebo"}
    assert all(origin == "node" for (_, callerid), origin in origins.items() if callerid == "/gazebo_helper")
    # Node publications on the world's own topics are recorded apart, never on the world's topic.
    assert ("/odom", "/gazebo_helper") not in origins and ("/clock", "/gazebo_helper") not in origins
    assert ("/rosgrade/ignored/odom", "/gazebo_helper") in origins
    assert any("published on /odom, which only the simulated robot" in d for d in case.result.diagnostics)
