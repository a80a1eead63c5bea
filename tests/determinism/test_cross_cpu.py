"""The grader on a CPU without AVX-512 (qemu's Haswell) gives the recordings and grades it gives on this one."""
from __future__ import annotations

import json
import platform
import shutil
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
import cross_cpu  # noqa: E402 - a script beside this test, not a package

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(platform.machine() != "x86_64", reason="emulates another x86_64 CPU: this machine is not one"),
    pytest.mark.skipif(cross_cpu.QEMU is None, reason="qemu-x86_64 is not installed (Debian: apt install qemu-user)"),
]


@pytest.fixture(scope="module")
def two_cpus(tmp_path_factory) -> tuple[Path, Path]:
    """move_circle's reference graded natively and by a grader on an emulated Haswell (about a minute)."""
    out = tmp_path_factory.mktemp("cross-cpu")
    target = cross_cpu.REPO / "reference_solutions" / "move_circle.py"
    for way in ("native", "haswell"):
        cross_cpu.check(target, out / way, way, ["move_circle"])
    return out / "native", out / "haswell"


def test_the_recordings_are_the_same_bytes_on_both_cpus(two_cpus) -> None:
    result = cross_cpu.compare(*two_cpus)
    assert result.different_files == []
    assert sum(name.endswith(".mcap") for name in result.same_files) == 3  # nominal, wheel_error, world_start


def test_the_grades_are_the_same_on_both_cpus(two_cpus) -> None:
    assert cross_cpu.compare(*two_cpus).different_grades == []


def test_measured_values_in_their_last_bits_are_told_apart_from_different_grades(tmp_path) -> None:
    for name, radius in (("a", 0.49995657394030524), ("b", 0.4999565739403053), ("c", 0.51)):
        (tmp_path / name).mkdir()
        (tmp_path / name / "report.json").write_text(json.dumps({"score": 10, "max_score": 10, "tasks": [
            {"id": "move_circle", "score": 10, "max_score": 10, "status": "graded", "criteria": [
                {"id": "radius", "score": 4, "passed": True, "feedback": "ok", "measured": {"radius": radius}}]}]}))
    last_bit = cross_cpu.compare(tmp_path / "a", tmp_path / "b")
    assert (last_bit.last_bits, last_bit.different_grades) == (["move_circle.radius.measured.radius"], [])
    assert cross_cpu.compare(tmp_path / "a", tmp_path / "c").different_grades == ["move_circle.radius.measured.radius"]


def test_the_comparison_sees_one_changed_bit_and_one_changed_grade(two_cpus, tmp_path) -> None:
    native, _ = two_cpus
    altered = tmp_path / "altered"
    shutil.copytree(native, altered)
    recording = altered / "move_circle" / "nominal.mcap"
    data = bytearray(recording.read_bytes())
    data[len(data) // 2] ^= 1
    recording.write_bytes(bytes(data))
    report = json.loads((altered / "report.json").read_text())
    report["tasks"][0]["criteria"][0]["score"] += 0.5
    (altered / "report.json").write_text(json.dumps(report))
    result = cross_cpu.compare(native, altered)
    assert result.different_files == ["move_circle/nominal.mcap"]
    assert result.different_grades == [f"move_circle.{report['tasks'][0]['criteria'][0]['id']}.score"]
