"""Whole runs of a rospy node calling turtlesim's services: spawn and drive a second turtle, lift the pen and teleport,
fail as rospy fails, reset; every call and reply is in the recording, and the recording repeats bit for bit."""
from __future__ import annotations

import hashlib
import re
from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario
from sim.turtle_canvas import DEFAULT_BACKGROUND
from sim.turtlesim import CANVAS_M, DT

NODE = Path(__file__).resolve().parent / "nodes" / "turtle_services.py"
CENTRE = CANVAS_M / 2
F32 = 1e-5  # poses are float32 on the wire

pytestmark = pytest.mark.slow


def run_node(tmp: Path, name: str):
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=5.0), nodes=(NodeSpec(script=NODE),))
    result = run(spec, tmp / f"{name}.mcap", tmp / f"{name}.log")
    return result, Recording.open(tmp / f"{name}.mcap")


@pytest.fixture(scope="module")
def services_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("turtle_services")
    result, rec = run_node(tmp, "first")
    printed = [(t, text) for t, stream, text in rec.output_lines() if stream == "stdout"]
    return tmp, result, rec, printed


def said(printed: list[tuple[float, str]], prefix: str) -> tuple[float, str]:
    """(sim time, line) of the one line the node printed that starts with ``prefix``."""
    found = [(t, text) for t, text in printed if text.startswith(prefix)]
    assert len(found) == 1, (prefix, printed)
    return found[0]


def test_the_node_ran_through(services_run) -> None:
    _, result, _, printed = services_run
    assert result.nodes[0].status == "exited", result.nodes[0].message
    assert said(printed, "done at")


def test_failures_raise_rospys_service_exceptions(services_run) -> None:
    _, _, _, printed = services_run
    assert said(printed, "spawn taken")[1] == "spawn taken failed: service [/spawn] responded with an error: b''"
    assert said(printed, "missing")[1] == "missing failed: service [/no_such_service] unavailable"
    assert said(printed, "wrong type")[1] == (
        "wrong type failed: unable to connect to service: remote error reported: client wants service /clear to have "
        "md5sum 937c9679a518e3a18d831e57125ea522, but it has d41d8cd98f00b204e9800998ecf8427e. Dropping connection.")
    assert said(printed, "kill nobody")[1] == "kill nobody failed: service [/kill] responded with an error: b''"
    assert said(printed, "gone")[1] == "gone failed: service [/turtle2/set_pen] unavailable"  # killed by /reset


def test_wait_for_service_returns_at_once_for_a_spawned_turtles_service(services_run) -> None:
    _, _, _, printed = services_run
    assert said(printed, "turtle2 serves")[0] == said(printed, "spawned")[0]


def test_wait_for_service_times_out_as_rospy_polling_every_0_3_s(services_run) -> None:
    _, _, _, printed = services_run
    t, line = said(printed, "wait failed")
    started = said(printed, "missing")[0]
    assert line.endswith("timeout exceeded while waiting for service /no_such_service")
    assert t == pytest.approx(started + 0.6)  # looks at +0, +0.3 and +0.6 s; 0.5 s have passed by the last


def test_the_spawned_turtle_drives_on_its_own_cmd_vel(services_run) -> None:
    _, _, rec, _ = services_run
    poses = [p for _, p in rec.messages("/turtle2/pose")]
    moving = sum(1 for p in poses if p.linear_velocity == 1.0)
    assert moving > 50  # ten commands 0.1 s apart, then the 1 s timeout
    assert poses[0].x == 2.0 and poses[-1].x == pytest.approx(2.0 + moving * DT, abs=F32)
    assert {round(p.y, 5) for p in poses} == {3.0} and {p.theta for p in poses} == {0.0}
    assert {p.linear_velocity for _, p in rec.messages("/turtle1/pose")} == {0.0}  # turtle1 was never driven


def test_teleports_with_the_pen_off_move_turtle1_and_draw_nothing(services_run) -> None:
    _, _, rec, _ = services_run
    (relative_t, _), = rec.messages("/rosgrade/service/turtle1/teleport_relative/request")
    (absolute_t, _), = rec.messages("/rosgrade/service/turtle1/teleport_absolute/request")
    poses = list(rec.messages("/turtle1/pose"))
    colours = dict(rec.messages("/turtle1/color_sensor"))
    after_relative = next(p for t, p in poses if t > relative_t)
    assert (after_relative.x, after_relative.y) == pytest.approx((CENTRE + 2.0, CENTRE), abs=F32)
    after_absolute = next(p for t, p in poses if t > absolute_t)
    assert (after_absolute.x, after_absolute.y, after_absolute.theta) == pytest.approx((1.0, 9.0, 1.5), abs=F32)
    assert {(c.r, c.g, c.b) for c in colours.values()} == {DEFAULT_BACKGROUND}  # no line under turtle1, ever


def test_reset_removes_turtle2_and_brings_turtle1_back(services_run) -> None:
    _, _, rec, _ = services_run
    (reset_t, _), = rec.messages("/rosgrade/service/reset/request")
    assert max(t for t, _ in rec.messages("/turtle2/pose")) <= reset_t
    back = [p for t, p in rec.messages("/turtle1/pose") if t > reset_t]
    assert back and all((p.x, p.y, p.theta) == pytest.approx((CENTRE, CENTRE, 0.0), abs=F32) for p in back)
    world_said = [m.msg for _, m in rec.messages("/rosout") if m.name == "/turtlesim"]
    assert world_said == [
        "Spawning turtle [turtle2] at x=[2.000000], y=[3.000000], theta=[0.000000]",
        "A turtled named [turtle1] already exists",
        "Tried to kill turtle [nobody], which does not exist",
        "Resetting turtlesim.",
        "Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]",
    ]


def test_every_call_and_its_outcome_is_recorded(services_run) -> None:
    _, _, rec, _ = services_run
    channels = {t.topic: t for t in rec.topics() if t.topic.startswith("/rosgrade/service/")}
    requests = [m for _, m in rec.messages("/rosgrade/service/spawn/request")]
    assert [(r.x, r.y, r.name) for r in requests] == [(2.0, 3.0, ""), (1.0, 1.0, "turtle1")]
    assert [m.name for _, m in rec.messages("/rosgrade/service/spawn/response")] == ["turtle2"]
    assert [m.data for _, m in rec.messages("/rosgrade/service/spawn/error")] == ["failed"]
    assert [m.data for _, m in rec.messages("/rosgrade/service/no_such_service/error")] == ["unavailable"]
    refused, = [m.data for _, m in rec.messages("/rosgrade/service/clear/error")]
    assert refused.startswith("refused: client wants service /clear to have md5sum 937c")
    assert channels["/rosgrade/service/spawn/request"].origin == "node"
    assert channels["/rosgrade/service/spawn/request"].callerid == "/turtle_services"
    assert channels["/rosgrade/service/spawn/response"].origin == "world"
    assert channels["/rosgrade/service/turtle1/set_pen/request"].type == "turtlesim/SetPenRequest"
    assert "/rosgrade/service/no_such_service/request" not in channels  # nothing served it
    # each call is stamped at the caller's sim time: the node's printed times follow the calls
    (spawned_t, _), = rec.messages("/rosgrade/service/spawn/response")
    assert re.fullmatch(r"spawned turtle2 at \d+\.\d{3}", said(services_run[3], "spawned")[1])
    assert spawned_t == pytest.approx(said(services_run[3], "spawned")[0] * 1e9)


def test_service_runs_are_bit_identical_on_repeat(services_run) -> None:
    tmp, _, _, _ = services_run
    run_node(tmp, "second")
    digest = [hashlib.sha256((tmp / f"{n}.mcap").read_bytes()).hexdigest() for n in ("first", "second")]
    assert digest[0] == digest[1]
