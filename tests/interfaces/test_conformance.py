"""The submission's interfaces as the real tool chains build them: rosgrade's classes and hashes against records of
real rosidl (ROS 2 venv: rosidl_adapter, rosidl_generator_type_description, rosidl_generator_py) and of Debian's
genmsg/genpy, taken by real_rosidl.py and real_genpy.py from the same files; live again where those are installed."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from grader.interfaces import catalog_for, run_interfaces
from grader.nodelib import pythonpath
from grader.nodelib.ros2.rosgrade_rosidl import _defs as node_defs
from grader.recording.ros2_messages import rihs01_hasher, ros2_catalog
from grader.workspace import read_workspace
from tests.interfaces.workspaces import package

HERE = Path(__file__).resolve().parent
EXAMPLE = HERE.parents[1] / "reference_solutions_ros2_cmake"
VENV = Path(os.environ.get("ROSGRADE_ROS2_VENV", "/opt/rosgrade-ros2-jazzy-venv"))
DEBIAN_PYTHON = "/usr/bin/python3"


def _ours(flavour: str, payload: dict, package: str, tmp: Path) -> dict:
    (tmp / "payload.json").write_text(json.dumps(payload))
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([pythonpath(flavour), str(HERE)])}
    out = subprocess.run([sys.executable, "-B", str(HERE / "ours.py"), flavour, str(tmp / "payload.json"), package],
                         capture_output=True, text=True, env=env, timeout=120, check=True)
    return json.loads(out.stdout)


def _record(name: str) -> dict:
    return json.loads((HERE / name).read_text())


# -- ROS 2 ---------------------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def ros2_interfaces():
    found = run_interfaces(read_workspace(EXAMPLE), "ros2")
    assert found.findings == []
    return found


def test_ros2_classes_behave_as_rosidl_generator_py_s(ros2_interfaces, tmp_path: Path) -> None:
    ours = _ours("ros2", ros2_interfaces.payload, "number_game_interfaces", tmp_path)["behaviour"]
    assert ours == _record("real_rosidl_record.json")["behaviour"]


def test_ros2_hashes_are_rosidl_s(ros2_interfaces) -> None:
    catalog = catalog_for("ros2", ros2_interfaces)
    real = _record("real_rosidl_record.json")["hashes"]
    services = {name for name in real if name.endswith(("MyNumberGame", "_SendGoal", "_GetResult"))}
    ours = {name: catalog.service_md5sum(name) if name in services else catalog.md5sum(name)
            for name in real if name.startswith("number_game_interfaces/")}
    assert ours == {name: value for name, value in real.items() if name.startswith("number_game_interfaces/")}
    assert len(ours) == 18  # a message, a service's 4 types, an action's 13
    payload = ros2_interfaces.payload
    assert payload["services"]["number_game_interfaces/srv/MyNumberGame"] == real[
        "number_game_interfaces/srv/MyNumberGame"]
    assert payload["actions"]["number_game_interfaces/action/ExploreForward"] == real[
        "number_game_interfaces/action/ExploreForward"]


def _venv_reason() -> str | None:
    if not (VENV / "bin" / "python").exists():
        return f"no ROS 2 venv at {VENV} (.ci/ros2-venv makes it)"
    return None


@pytest.mark.skipif(_venv_reason() is not None, reason=str(_venv_reason()))
def test_ros2_record_is_what_the_real_generators_give_now(tmp_path: Path) -> None:
    env = {**os.environ, "AMENT_PREFIX_PATH": str(VENV), "PYTHONPATH": str(HERE)}
    out = subprocess.run([str(VENV / "bin" / "python"), str(HERE / "real_rosidl.py"),
                          str(EXAMPLE / "number_game_interfaces"), str(VENV), str(tmp_path)],
                         capture_output=True, text=True, env=env, timeout=300, check=True, cwd=HERE)
    assert json.loads(out.stdout) == _record("real_rosidl_record.json")


@pytest.mark.skipif(_venv_reason() is not None, reason=str(_venv_reason()))
def test_built_in_hashes_as_rosidl_computes_them() -> None:
    """Every type the venv's wheels describe (share/<pkg>/<ns>/<Name>.json) that rosgrade's catalog has: rosidl's
    hash from the catalog's definitions, char read as uint8 as rosidl_adapter reads it."""
    hasher = rihs01_hasher(ros2_catalog().typestore.fielddefs)
    compared, different = 0, []
    for path in sorted((VENV / "share").glob("*/*/*.json")):
        name = "/".join(path.with_suffix("").parts[-3:])
        if name not in hasher.fielddefs:
            continue
        real = {item["type_name"]: item["hash_string"] for item in json.loads(path.read_text())["type_hashes"]}
        compared += 1
        if hasher.hash_rihs01(name) != real[name]:
            different.append(name)
    assert compared >= 100
    assert different == []


@pytest.mark.skipif(_venv_reason() is not None, reason=str(_venv_reason()))
def test_node_table_hashes_as_rosidl_computes_them() -> None:
    """What a node's classes say (rosgrade_rosidl's table, services too) for every type the venv describes."""
    ours = {name: json.loads(entry)[2] for name, entry in node_defs.MESSAGES.items()} | node_defs.SERVICES
    real = {}
    for name in ours:
        path = VENV / "share" / f"{name}.json"
        if path.exists():
            real[name] = {item["type_name"]: item["hash_string"]
                          for item in json.loads(path.read_text())["type_hashes"]}[name]
    assert len(real) >= 100
    assert {name: ours[name] for name in real} == real


# -- ROS 1 ---------------------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def ros1_interfaces():
    found = run_interfaces(read_workspace(HERE / "game_msgs"), "ros1")
    assert found.findings == []
    return found


def test_ros1_classes_behave_as_genpy_s(ros1_interfaces, tmp_path: Path) -> None:
    ours = _ours("ros1", ros1_interfaces.payload, "game_msgs", tmp_path)["behaviour"]
    assert ours == _record("real_genpy_record.json")["behaviour"]


def test_ros1_md5sums_are_genmsg_s(ros1_interfaces) -> None:
    catalog = catalog_for("ros1", ros1_interfaces)
    real = _record("real_genpy_record.json")["md5sums"]
    assert {name: catalog.service_md5sum(name) if name.endswith("Game") else catalog.md5sum(name)
            for name in real} == real


def _debian_reason() -> str | None:
    probe = subprocess.run([DEBIAN_PYTHON, "-c", "import genpy, genmsg, std_msgs.msg, geometry_msgs.msg"],
                           capture_output=True) if Path(DEBIAN_PYTHON).exists() else None
    return None if probe is not None and probe.returncode == 0 else "Debian's python3-genpy/genmsg not installed"


@pytest.mark.skipif(_debian_reason() is not None, reason=str(_debian_reason()))
def test_ros1_record_is_what_genpy_gives_now(tmp_path: Path) -> None:
    out = subprocess.run([DEBIAN_PYTHON, str(HERE / "real_genpy.py"), str(HERE / "game_msgs"), str(tmp_path)],
                         capture_output=True, text=True, timeout=120, check=True, cwd=HERE)
    assert json.loads(out.stdout) == _record("real_genpy_record.json")


# genmsg's md5sums of actionlib's TwoInts action (Debian python3-actionlib 1.14.0, `actionlib.msg`), whose
# definition is the one written below; an md5sum does not depend on the package's name.
TWO_INTS = "int64 a\nint64 b\n---\nint64 sum\n---\n"
TWO_INTS_MD5 = {"TwoIntsAction": "6d1aa538c4bd6183a2dfb7fcac41ee50",
                "TwoIntsActionGoal": "684a2db55d6ffb8046fb9d6764ce0860",
                "TwoIntsActionResult": "3ba7dea8b8cddcae4528ade4ef74b6e7",
                "TwoIntsActionFeedback": "aae20e09065c3809e8a8e87c4c8953fd",
                "TwoIntsGoal": "36d09b846be0b371c5f190354dd3153e", "TwoIntsResult": "b88405221c77b1878a3cbbfff53428d7",
                "TwoIntsFeedback": "d41d8cd98f00b204e9800998ecf8427e"}


def test_ros1_action_messages_are_genmsg_s(tmp_path: Path) -> None:
    package(tmp_path, "two_ints_msgs", {"action/TwoInts.action": TWO_INTS}, flavour="ros1")
    found = run_interfaces(read_workspace(tmp_path), "ros1")
    catalog = catalog_for("ros1", found)
    assert {name: catalog.md5sum(f"two_ints_msgs/{name}") for name in TWO_INTS_MD5} == TWO_INTS_MD5
    # the node's genpy computes the same from what it is given (GoalID and GoalStatus included)
    script = ("import json, sys, rosgrade_interfaces\nrosgrade_interfaces.install(json.load(open(sys.argv[1])))\n"
              "import two_ints_msgs.msg as m\nprint(json.dumps({n: getattr(m, n)._md5sum for n in sys.argv[2:]}))\n")
    (tmp_path / "payload.json").write_text(json.dumps(found.payload))
    out = subprocess.run([sys.executable, "-B", "-c", script, str(tmp_path / "payload.json"), *TWO_INTS_MD5],
                         capture_output=True, text=True, env={**os.environ, "PYTHONPATH": pythonpath("ros1")},
                         timeout=60, check=True)
    assert json.loads(out.stdout) == TWO_INTS_MD5


@pytest.mark.skipif(_debian_reason() is not None, reason=str(_debian_reason()))
def test_two_ints_md5sums_are_debian_actionlib_s() -> None:
    script = "import json, actionlib.msg as m, sys\nprint(json.dumps({n: getattr(m, n)._md5sum for n in sys.argv[1:]}))"
    out = subprocess.run([DEBIAN_PYTHON, "-c", script, *TWO_INTS_MD5], capture_output=True, text=True, timeout=60)
    if out.returncode != 0:
        pytest.skip("Debian's python3-actionlib is not installed")
    assert json.loads(out.stdout) == TWO_INTS_MD5


def test_ros2_cdr_bytes_are_real_rclpy_s(ros2_interfaces, tmp_path: Path) -> None:
    """real_cdr_record.json: real rclpy's bytes of cdr_values.py's messages, the package built for it by
    build_real_interfaces.sh (CMake and the ROS 2 wheels' rosidl tool chain) and serialized by real_cdr.py."""
    (tmp_path / "payload.json").write_text(json.dumps(ros2_interfaces.payload))
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([pythonpath("ros2"), str(HERE)])}
    out = subprocess.run([sys.executable, "-B", str(HERE / "ours_cdr.py"), str(tmp_path / "payload.json"),
                          str(HERE / "real_cdr_record.json")], capture_output=True, text=True, env=env, timeout=120,
                         check=True)
    assert json.loads(out.stdout) == {name: [True, True] for name in _record("real_cdr_record.json")}
    real = {name: bytes.fromhex(text) for name, text in _record("real_cdr_record.json").items()}
    catalog = catalog_for("ros2", ros2_interfaces)  # the grader reads them too
    guess = catalog.decode("number_game_interfaces/msg/Guess", real["Guess"])
    assert (guess.value, guess.where.x, guess.name, list(guess.history)) == (42, 1.5, "seven", [1, 2, 3])
    feedback = catalog.decode("number_game_interfaces/action/ExploreForward_FeedbackMessage", real["FeedbackMessage"])
    assert feedback.feedback.current_distance_travelled == 2.5
