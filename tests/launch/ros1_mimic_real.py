"""Measure with Debian's real roscpp where turtlesim's mimic subscribes and publishes for a set of remaps and
namespaces: mimic.cpp keeps its topics under ``ros::NodeHandle("input")`` and ``("output")``, whose namespaces roscpp
resolves and remaps before it adds the topic.

Noetic's turtlesim is not in Debian, so ``ros1_mimic_names_probe.cpp`` (ours: the same two NodeHandles, subscription
and publication) is compiled against Debian's libroscpp and run beside a private rosmaster (tests/conformance's
``RealRos``). ``python3 tests/launch/ros1_mimic_real.py`` records the names into ``ros1_mimic_roscpp_names.json``,
which the tests compare rosgrade's mimic with where roscpp cannot be built.
"""
from __future__ import annotations

import json
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "conformance"))
from real_ros import NOT_INSTALLED, RealRos, real_ros_available  # noqa: E402

PROBE = HERE / "ros1_mimic_names_probe.cpp"
RECORDED = HERE / "ros1_mimic_roscpp_names.json"
HEADER = Path("/usr/include/ros/node_handle.h")  # Debian's libroscpp-dev


class MimicRealError(Exception):
    """The probe could not be built or did not print its names."""


@dataclass(frozen=True)
class NameCase:
    """A mimic started with these remap arguments in this namespace; its name is unique in a run of all cases."""

    node: str
    remaps: tuple[str, ...]
    namespace: str | None = None

    @property
    def args(self) -> tuple[str, ...]:
        return (*self.remaps, f"__name:={self.node}")


CASES = (
    NameCase("mimic", ("input:=turtlesim1/turtle1", "output:=turtlesim2/turtle1")),  # the roslaunch tutorial's
    NameCase("mimic_topics", ("input/pose:=/a/pose", "output/cmd_vel:=/b/cmd_vel")),
    NameCase("mimic_both", ("input:=/c", "input/pose:=/c_unused", "output:=/c_out")),
    NameCase("mimic_ns", ("input:=turtle1", "output:=/d_out"), "ns1"),
    NameCase("mimic_plain", (), "sim"),
    NameCase("mimic_private", ("input:=~in", "output:=~out"), "ns6"),
    NameCase("mimic_root", ("input:=/", "output:=/g")),
)


def unavailable_reason() -> str | None:
    """Why real roscpp cannot be measured here (None: it can)."""
    if shutil.which("g++") is None or shutil.which("pkg-config") is None:
        return "g++ and pkg-config are needed to build the roscpp probe"
    if not HEADER.is_file():
        return "Debian's libroscpp-dev is not installed"
    if not real_ros_available():
        return NOT_INSTALLED
    return None


def _build(folder: Path) -> Path:
    flags = subprocess.run(["pkg-config", "--cflags", "--libs", "roscpp"], capture_output=True, text=True, timeout=30)
    if flags.returncode != 0:
        raise MimicRealError(f"pkg-config knows no roscpp: {flags.stderr.strip()}")
    binary = folder / "mimic_names_probe"
    built = subprocess.run(["g++", "-O0", str(PROBE), "-o", str(binary), *flags.stdout.split()],
                           capture_output=True, text=True, timeout=300)
    if built.returncode != 0:
        raise MimicRealError(f"the roscpp probe did not build: {built.stderr[-2000:]}")
    return binary


def measure() -> dict[str, list[str]]:
    """Each case's node name, subscribed topic and published topic as real roscpp resolves them."""
    folder = Path(tempfile.mkdtemp(prefix="rosgrade-mimic-names-"))
    try:
        binary = _build(folder)
        names = {}
        with RealRos(folder / "ros") as real:
            for case in CASES:
                env = real.env() | ({"ROS_NAMESPACE": case.namespace} if case.namespace else {})
                ran = subprocess.run([str(binary), *case.args], env=env, capture_output=True, text=True, timeout=30)
                printed = ran.stdout.split()
                if ran.returncode != 0 or len(printed) != 3:
                    raise MimicRealError(f"{case.node}: the probe printed {ran.stdout!r} ({ran.stderr[-500:]})")
                names[case.node] = printed
        return names
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def recorded() -> dict[str, list[str]]:
    """The names measured last with real roscpp (``RECORDED``)."""
    return json.loads(RECORDED.read_text())


if __name__ == "__main__":
    if (reason := unavailable_reason()) is not None:
        sys.exit(reason)
    RECORDED.write_text(json.dumps(measure(), indent=1) + "\n")
    print(f"wrote {RECORDED}")
