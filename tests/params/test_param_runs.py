"""Whole runs on the run's parameter server: one node's changes reach another at its next tick; turtlesim's
background follows background_r/g/b on /clear and /reset, on the canvas, the colour sensor and the report's picture
redrawn from the recording; a launch-given colour is there from the start; recordings repeat bit for bit."""
from __future__ import annotations

import hashlib
import io
import json
from pathlib import Path

import numpy as np
import pytest
from matplotlib.image import imread

from grader.metrics.pen import redraw
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.reports.plots import task_plots
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import Session
from sim import Scenario
from sim.turtlesim import DEFAULT_PEN, UPDATE_NS

NODES = Path(__file__).resolve().parent / "nodes"
EPOCH = 1_700_000_000.0  # the wall clock a turtlesim node reads is world time from this epoch

pytestmark = pytest.mark.slow


def session_run(tmp: Path, name: str, nodes: tuple[NodeSpec, ...], duration: float) -> tuple[Session, Recording]:
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=duration), nodes=nodes)
    session = Session(spec, tmp / f"{name}.mcap", tmp / f"{name}.log")
    result = session.run()
    assert all(n.status == "exited" for n in result.nodes), [n.message for n in result.nodes]
    return session, Recording.open(tmp / f"{name}.mcap")


def printed(recording: Recording, callerid: str) -> list[str]:
    return [m.data for _, m in recording.messages("/rosgrade/stdout", callerid)]


def colours(recording: Recording) -> list[tuple[int, tuple[int, int, int]]]:
    """(time, colour) each time turtle1's colour sensor reads a new colour."""
    seen: list[tuple[int, tuple[int, int, int]]] = []
    for t, m in recording.messages("/turtle1/color_sensor"):
        if not seen or seen[-1][1] != (m.r, m.g, m.b):
            seen.append((t, (m.r, m.g, m.b)))
    return seen


def first_update_after(t_ns: int) -> int:
    """The first world update after a call handled at t_ns (a call at an update's time comes after it)."""
    return (t_ns // UPDATE_NS + 1) * UPDATE_NS


# -- two nodes ----------------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def shared(tmp_path_factory):
    """The reader is node 0: at a tick both run, it runs first, so it sees the setter's change one tick later."""
    given = {"/shared/gone": 1, "/turtlesim/background_r": 10}
    nodes = (NodeSpec(script=NODES / "param_reader.py", params=given),
             NodeSpec(script=NODES / "param_setter.py", params=given))
    return session_run(tmp_path_factory.mktemp("shared"), "shared", nodes, 2.0)


def _at(line: str) -> float:
    return float(line.split()[-1]) - EPOCH


def test_the_reader_sees_each_change_at_its_next_tick(shared) -> None:
    _, recording = shared
    setter, reader = printed(recording, "/setter"), printed(recording, "/reader")
    set_at = _at(next(line for line in setter if line.startswith("set ")))
    changed_at = _at(next(line for line in setter if line.startswith("changed ")))
    seen = [(float(line.split()[0]) - EPOCH, line.split(" ", 1)[1]) for line in reader if line[0].isdigit()]
    assert seen == [
        (pytest.approx(0.1), "(None, True, None)"),  # the start tree: /shared/gone from the task's params
        (pytest.approx(set_at + 0.01), "(42, False, {'a': 1, 'b': [1, 2.5, 'x']})"),
        (pytest.approx(changed_at + 0.01), "(44, False, {'a': 1, 'b': [1, 2.5, 'x'], 'c': True})"),
    ]
    assert reader[-1] == "names ['/shared/ns/a', '/shared/ns/b', '/shared/ns/c', '/shared/value']"
    assert "delete missing: KeyError '/shared/never'" in setter


def test_the_recording_holds_the_start_tree_then_every_change_by_whom(shared) -> None:
    _, recording = shared
    by = {info.callerid: info.origin for info in recording.topics() if info.topic == "/rosgrade/param"}
    assert by == {"/rosgrade": "grader", "/setter": "node"}
    changes = [json.loads(m.data) for _, m in recording.messages("/rosgrade/param")]
    assert changes[0] == {"op": "set", "name": "/", "value": {
        "use_sim_time": False, "shared": {"gone": 1},
        "turtlesim": {"background_r": 10, "background_g": 86, "background_b": 255}}}
    assert [(c["op"], c["name"]) for c in changes[1:]] == [
        ("set", "/shared/value"), ("set", "/shared/ns"), ("delete", "/shared/gone"), ("set", "/shared/ns/c"),
        ("set", "/shared/value"), ("delete", "/shared/value"), ("set", "/shared/value")]


def test_a_colour_given_before_the_start_is_the_canvas_from_the_start(shared) -> None:
    session, recording = shared
    assert [colour for _, colour in colours(recording)] == [(10, 86, 255)]
    assert np.array_equal(redraw(RunData.from_recording(recording)).canvas.pixels, session.world.canvas.pixels)
    assert bool(np.all(session.world.canvas.pixels == np.array((10, 86, 255), dtype=np.uint8)))


# -- turtlesim's background ---------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def painted(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("background")
    session, recording = session_run(tmp, "first", (NodeSpec(script=NODES / "turtle_background.py"),), 4.0)
    return tmp, session, recording


def test_the_node_reads_the_defaults_turtlesim_set_at_its_start(painted) -> None:
    _, _, recording = painted
    assert printed(recording, "/background")[0] == "start [69, 86, 255]"


def test_the_colour_sensor_sees_each_background_from_the_update_after_the_call(painted) -> None:
    _, _, recording = painted
    lines = printed(recording, "/background")
    cleared = round(_at(next(line for line in lines if line.startswith("clear at "))) * 1e9) + 2_000_000_000
    reset = round(_at(next(line for line in lines if line.startswith("reset at "))) * 1e9) + 2_000_000_000
    seen = colours(recording)
    assert seen[0][1] == (69, 86, 255)
    assert seen[1] == (first_update_after(cleared), (255, 129, 0))  # 128.5 read as roscpp reads an int: 129
    assert seen[2][1] == DEFAULT_PEN  # driving over its own line
    # r deleted and b a string: their defaults; g 300: its low 8 bits
    assert seen[3] == (first_update_after(reset), (69, 300 & 0xFF, 255))
    assert seen[4][1] == DEFAULT_PEN and len(seen) == 5


def test_the_picture_redrawn_from_the_recording_is_the_worlds_canvas(painted) -> None:
    _, session, recording = painted
    drawing = redraw(RunData.from_recording(recording))
    assert np.array_equal(drawing.canvas.pixels, session.world.canvas.pixels)
    assert {tuple(int(c) for c in p) for p in drawing.canvas.pixels.reshape(-1, 3)} == {(69, 44, 255), DEFAULT_PEN}


def test_the_reports_turtlesim_window_is_drawn_on_the_runs_background(painted) -> None:
    _, _, recording = painted
    (canvas,) = [p for p in task_plots("turtle_move", "nominal", recording) if p.name == "canvas"]
    shown = {tuple(px) for px in np.round(imread(io.BytesIO(canvas.png))[..., :3] * 255).astype(int).reshape(-1, 3)}
    assert (69, 44, 255) in shown and (69, 86, 255) not in shown


def test_the_recording_repeats_bit_for_bit(painted) -> None:
    tmp, _, _ = painted
    session_run(tmp, "second", (NodeSpec(script=NODES / "turtle_background.py"),), 4.0)
    digest = [hashlib.sha256((tmp / f"{name}.mcap").read_bytes()).hexdigest() for name in ("first", "second")]
    assert digest[0] == digest[1]
