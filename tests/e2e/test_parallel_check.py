"""`check -j 2` writes exactly what `check -j 1` writes: the report JSON and every recording, byte for byte."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.cli import main

pytestmark = pytest.mark.slow

# A single-script task, a subscriber task and a two-node launch-file task: 7 runs in all.
TASKS = ("move_circle", "odom_subscriber", "move_distance_launch")


@pytest.fixture(scope="module")
def checked(tmp_path_factory: pytest.TempPathFactory, reference_dir: Path) -> dict[int, Path]:
    outs = {}
    for jobs in (1, 2):
        out = tmp_path_factory.mktemp(f"j{jobs}") / "out"
        args = ["check", str(reference_dir), "--out", str(out), "-j", str(jobs), "--json"]
        for task in TASKS:
            args += ["--task", task]
        assert main(args) == 0
        outs[jobs] = out
    return outs


def _files(out: Path, pattern: str) -> dict[str, bytes]:
    return {p.relative_to(out).as_posix(): p.read_bytes() for p in sorted(out.rglob(pattern))}


def test_report_json_is_identical(checked: dict[int, Path]) -> None:
    one, two = (checked[j].joinpath("report.json").read_text() for j in (1, 2))
    assert one.replace(str(checked[1]), "OUT") == two.replace(str(checked[2]), "OUT")


def test_recordings_are_byte_identical(checked: dict[int, Path]) -> None:
    one, two = _files(checked[1], "*.mcap"), _files(checked[2], "*.mcap")
    assert len(one) == 7 and one == two


def test_node_logs_are_identical(checked: dict[int, Path]) -> None:
    one, two = _files(checked[1], "*.log"), _files(checked[2], "*.log")
    assert one and one == two


def test_plots_are_byte_identical(checked: dict[int, Path]) -> None:
    # -j 2 draws them in two worker processes, a share of the recordings each
    one, two = _files(checked[1], "*.png"), _files(checked[2], "*.png")
    assert len(one) >= 7 and one == two


def test_the_report_pages_differ_only_in_the_output_folder(checked: dict[int, Path]) -> None:
    for page in ("report.md", "report.html"):
        one, two = (checked[j].joinpath(page).read_text() for j in (1, 2))
        assert one.replace(str(checked[1]), "OUT") == two.replace(str(checked[2]), "OUT")
