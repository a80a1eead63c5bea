"""Several student nodes from one launch file in one run: names, namespaces, params, remaps, node-to-node topics,
output="log", required="true", and bit-identical recordings on repeat with the other core busy."""
from __future__ import annotations

import hashlib
import multiprocessing
from pathlib import Path

import pytest

from grader.launch import find_packages, read_launch
from grader.launch.specs import node_specs
from grader.recording import Recording
from grader.runtime import RunSpec
from grader.runtime.session import run
from sim import Scenario

pytestmark = pytest.mark.slow

WORKSPACE = Path(__file__).parent / "ws" / "src"
LAUNCH = WORKSPACE / "multi_nodes" / "launch" / "multi.launch"
SCENARIO = Scenario(duration=6.0)  # starts at 2.0 s; the required stopper ends after 3 sim seconds


def _spec(**args: str) -> RunSpec:
    packages = find_packages(WORKSPACE)
    nodes, _ = node_specs(read_launch(LAUNCH, args, packages), packages)
    return RunSpec(scenario=SCENARIO, nodes=nodes)


def _run(tmp: Path, name: str, spec: RunSpec | None = None):
    result = run(spec or _spec(), tmp / f"{name}.mcap", tmp / f"{name}.log")
    return result, Recording.open(tmp / f"{name}.mcap")


@pytest.fixture(scope="module")
def launched(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("multi")
    result, recording = _run(tmp, "run")
    return result, recording, tmp


def _texts(recording: Recording, topic: str, callerid: str | None = None) -> list[str]:
    return [msg.data for _, msg in recording.messages(topic, callerid)]


def test_each_node_has_its_launch_name_and_namespace(launched):
    result, _, _ = launched
    assert [n.name for n in result.nodes] == ["/talker", "/robot1/listener", "/stopper"]


def test_remapped_topic_reaches_the_namespaced_node_and_both_are_recorded(launched):
    _, recording, _ = launched
    said = _texts(recording, "/robot1/chatter", "/talker")
    heard = _texts(recording, "/robot1/heard", "/robot1/listener")
    assert len(said) >= 10
    assert heard == [f"/robot1/listener heard {text}" for text in said]


def test_params_reach_every_node_private_and_global(launched):
    _, recording, _ = launched
    said = _texts(recording, "/robot1/chatter")
    assert said[0] == "hello 1"  # /greeting; message 0 went out before the publisher had connected
    listener_out = _texts(recording, "/rosgrade/stdout", "/robot1/listener")
    assert listener_out[0] == "I am /robot1/listener in /robot1/ greeting hello"
    times = [t for t, _ in recording.messages("/robot1/chatter")]
    assert times[-1] - times[-2] == 250_000_000  # ~rate = 4 Hz from the node's own <param>


def test_a_required_node_that_exits_shuts_the_others_down(launched):
    result, _, _ = launched
    stopper = result.nodes[2]
    assert stopper.status == "exited" and 5.0 <= stopper.ended_s <= 5.2  # slept 3 s from the start at 2 s
    assert result.shutdown_requested_s == stopper.ended_s
    assert [n.ended_s for n in result.nodes] == [stopper.ended_s] * 3
    assert any('required="true"' in d for d in result.diagnostics)


def test_output_log_sends_text_to_the_node_log_not_the_screen(launched):
    _, recording, tmp = launched
    screen = (tmp / "run.log").read_text()
    assert "said hello 1" in screen and "I am" not in screen
    assert "I am /robot1/listener" in (tmp / "run.node1.log").read_text()
    assert _texts(recording, "/rosgrade/stdout", "/stopper") == ["stopper done"]  # recorded either way


def test_without_required_the_others_run_to_the_end(tmp_path):
    result, _ = _run(tmp_path, "long", _spec(stop_after="10"))
    assert result.shutdown_requested_s is None
    assert [n.status for n in result.nodes] == ["stopped_at_end"] * 3


def _spin(stop) -> None:
    while not stop.is_set():
        pass


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _with_the_other_core_busy(action):
    stop = multiprocessing.Event()
    hog = multiprocessing.Process(target=_spin, args=(stop,))
    hog.start()
    try:
        return action()
    finally:
        stop.set()
        hog.join()


def test_recording_is_bit_identical_on_repeat_with_the_other_core_busy(launched, tmp_path):
    _, _, first_dir = launched
    _with_the_other_core_busy(lambda: _run(tmp_path, "again"))
    assert _digest(first_dir / "run.mcap") == _digest(tmp_path / "again.mcap")


def test_square_mover_and_printer_from_one_launch_file_record_bit_identically(tmp_path):
    """Two nodes that both read /odom while one drives: the reference launch file of square_odom_launch."""
    reference = Path(__file__).resolve().parents[2] / "reference_solutions"
    packages = find_packages(reference)
    nodes, _ = node_specs(read_launch(reference / "launch" / "square_and_odom.launch", {}, packages), packages)
    spec = RunSpec(scenario=Scenario(duration=25.0), nodes=nodes)
    first, _ = _run(tmp_path, "first", spec)
    second, recording = _with_the_other_core_busy(lambda: _run(tmp_path, "second", spec))
    assert _digest(tmp_path / "first.mcap") == _digest(tmp_path / "second.mcap")
    assert first.nodes == second.nodes
    assert recording.odometry().x.max() > 0.9  # it drove, and the printer printed while it did
    assert len(_texts(recording, "/rosgrade/stdout", "/odom_subscriber")) > 50
