"""Scenario publications against Debian's real `rostopic pub` 1.15.15: what a rospy node hears from a latched
`rostopic pub` and from `rostopic pub -r` (who sends it, which subscriber gets it, what a later subscriber of the
node gets), and how long `rostopic pub -1` stays; rosgrade's run of the same listener must hear the same."""
from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from real_ros import NOT_INSTALLED, REAL_PYTHON, RealRos, real_ros_available  # noqa: E402

from grader.recording import Recording  # noqa: E402
from grader.runtime import NodeSpec, RunSpec  # noqa: E402
from grader.runtime.scenario_topics import ONCE_STAY_NS  # noqa: E402
from grader.runtime.session import run  # noqa: E402
from sim import Scenario  # noqa: E402

pytestmark = pytest.mark.slow

LISTENER = Path(__file__).resolve().parents[1] / "runtime" / "nodes" / "topics" / "rospy_listener.py"
ROSTOPIC = "/usr/bin/rostopic"


def _heard(stdout: str) -> list[tuple[str, str, str]]:
    """(subscriber, data, which command sent it) per line; real callerids are anonymous, so each gets a letter."""
    names: dict[str, str] = {}
    heard = []
    for line in stdout.splitlines():
        subscriber, data, callerid, _ = line.split()
        heard.append((subscriber, data, names.setdefault(callerid, chr(ord("A") + len(names)))))
    return heard


def _shape(heard: list[tuple[str, str, str]]) -> list[tuple[str, str, str]]:
    """The first message each subscriber got from each command (the rate's count depends on wall timing)."""
    seen, shape = set(), []
    for item in heard:
        if item not in seen:
            seen.add(item)
            shape.append(item)
    return shape


@pytest.fixture(scope="module")
def real_heard(tmp_path_factory: pytest.TempPathFactory) -> list[tuple[str, str, str]]:
    if not real_ros_available() or not Path(ROSTOPIC).exists():
        pytest.skip(NOT_INSTALLED + " (or rostopic)")
    with RealRos(tmp_path_factory.mktemp("realpub")) as ros:
        commands = [subprocess.Popen([REAL_PYTHON, ROSTOPIC, "pub", *args], env=ros.env(), start_new_session=True,
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                    for args in (["/chatter", "std_msgs/String", "data: hi"],
                                 ["-r", "2", "/chatter", "std_msgs/String", "data: r"])]
        try:
            time.sleep(3.0)  # both commands up (imports, registration) before the listener starts
            result = ros.run_probe(LISTENER, duration=5.0)
        finally:
            for command in commands:
                command.kill()
                command.wait(5)
    return _heard(result.stdout)


def test_real_rostopic_pub_latches_for_later_subscribers_and_rate_does_not(real_heard) -> None:
    # one node per command; the early subscriber hears both, the node's later one gets the latched message at once
    assert _shape(real_heard)[:2] in ([("early", "hi", "A"), ("early", "r", "B")],
                                      [("early", "r", "A"), ("early", "hi", "B")])
    latched = next(sender for _, data, sender in real_heard if data == "hi")
    late = [item for item in real_heard if item[0] == "late"]
    assert late[0] == ("late", "hi", latched)


def test_rosgrade_listener_hears_what_real_rostopic_pub_gives(real_heard, tmp_path) -> None:
    scenario = Scenario(duration=5.0, publications=[
        {"t": 0.0, "topic": "/chatter", "type": "std_msgs/String", "values": {"data": "hi"}},
        {"t": 0.0, "topic": "/chatter", "type": "std_msgs/String", "values": {"data": "r"}, "rate": 2}])
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=LISTENER),)), tmp_path / "r.mcap", tmp_path / "r.log")
    ours = _heard("\n".join(line.text for line in Recording.open(tmp_path / "r.mcap").output_lines()))
    rename = {"A": "B", "B": "A"} if _shape(real_heard)[0][1] != _shape(ours)[0][1] else {"A": "A", "B": "B"}
    assert _shape([(s, d, rename[c]) for s, d, c in ours]) == _shape(real_heard)


def test_real_rostopic_pub_once_stays_as_long_as_ours(tmp_path) -> None:
    if not real_ros_available() or not Path(ROSTOPIC).exists():
        pytest.skip(NOT_INSTALLED + " (or rostopic)")
    with RealRos(tmp_path / "once") as ros:
        started = time.monotonic()
        subprocess.run([REAL_PYTHON, ROSTOPIC, "pub", "-1", "/chatter", "std_msgs/String", "data: x"], env=ros.env(),
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=30, check=True)
        elapsed = time.monotonic() - started
    # its start-up (imports, registration) comes on top of the stay
    assert ONCE_STAY_NS / 1e9 <= elapsed < ONCE_STAY_NS / 1e9 + 3.0
