"""Every report of the reference solutions and the example submissions (TurtleBot, Husky, turtlesim; ROS 1 and ROS 2)
has a working replay per run in a real headless Chromium, and the pages stay within their sizes."""
from __future__ import annotations

import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from grader.metrics.run import RunData
from grader.recording import Recording
from grader.reports.folder import write_report_folder
from grader.reports.replay import scenario_times
from tests.browser import Browser, chromium

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(chromium() is None, reason="no chromium installed (Debian: apt-get install chromium)")]

ROOT = Path(__file__).resolve().parents[2]
EXPECTED = tomllib.loads((ROOT / "submissions_example" / "EXPECTED.toml").read_text())
SUBMISSIONS = [("reference_solutions", ()), ("reference_solutions_turtlesim", ()),
               ("reference_solutions_ros2/part2_navigation", ()),
               *((f"submissions_example/{student}", tuple(sorted(tasks))) for student, tasks in EXPECTED.items())]
# A run's replay data; the page: what every page has (script, style, a task's plots and pictures: a turtlesim task of
# three runs is 576 KB) and then per run (the reference solutions' pages run 70-80 KB a run)
RUN_BYTES, PAGE_BYTES, PAGE_BYTES_PER_RUN = 300_000, 800_000, 100_000
POSE = re.compile(r"(?P<name>[\w/]+) at x (?P<x>-?[\d.]+) m, y (?P<y>-?[\d.]+) m")


@pytest.fixture(scope="module")
def browser():
    with Browser() as browser:
        yield browser


def recorded_at(path: str, seconds: float) -> tuple[RunData, tuple[float, float]]:
    """The run as scoring reads it, and where the robot (turtle1) was ``seconds`` after the start."""
    recording = Recording.open(path)
    start, shutdown_at = scenario_times(recording)
    run = RunData.from_recording(recording, start, shutdown_at)
    path_ = run.trajectory("ground_truth")
    t = start + seconds
    return run, (float(np.interp(t, path_.t, path_.x)), float(np.interp(t, path_.t, path_.y)))


@pytest.mark.parametrize("folder,tasks", SUBMISSIONS, ids=[s for s, _ in SUBMISSIONS])
def test_every_run_has_a_working_replay(graded, browser, tmp_path, folder, tasks):
    report = graded(ROOT / folder, tasks)
    files = write_report_folder(report, tmp_path / "report")
    recordings = {(t.id, Path(r).stem): r for t in report.tasks for r in t.recordings}
    assert sorted((r.task, r.scenario) for r in files.replays) == sorted(recordings)
    assert all(len(r.data.encode()) <= RUN_BYTES for r in files.replays)
    assert files.html.stat().st_size < PAGE_BYTES + PAGE_BYTES_PER_RUN * len(recordings)
    again = write_report_folder(report, tmp_path / "again")
    assert again.html.read_bytes() == files.html.read_bytes()  # the same recordings, the same page
    browser.events.clear()
    browser.open(files.html)
    assert browser.errors() == []
    for replay in files.replays:
        span = browser.js(f"window.rosgradeReplays[{replay.anchor!r}].data.span")
        middle = round((span[0] + span[1]) / 2, 2)
        browser.js(f"""(() => {{ const range = document.getElementById({replay.anchor + '-time'!r});
            range.value = {middle}; range.dispatchEvent(new Event('input')); }})()""")
        shown = browser.js(f"""(() => {{ const r = window.rosgradeReplays[{replay.anchor!r}];
            return [r.t, r.pose.textContent, Array.from(r.log.children).filter(li => !li.hidden)
                    .map(li => li.textContent)]; }})()""")
        run, (x, y) = recorded_at(recordings[(replay.task, replay.scenario)], shown[0])
        pose = next(m for m in POSE.finditer(shown[1]) if m["name"] in ("robot", "turtle1"))
        assert (float(pose["x"]), float(pose["y"])) == pytest.approx((x, y), abs=0.05), (replay.anchor, shown)
        # the page keeps times to 1/100 s
        printed = [line.message()[1] for line in run.lines if round(line.t - run.start_time, 2) <= shown[0]]
        if printed and len(printed) < 300:
            assert printed[-1][:100] in shown[2][-1], (replay.anchor, shown[2][-3:])
        elif not printed:
            assert shown[2] == ["Nothing printed yet."]
    for link in browser.js("Array.from(document.querySelectorAll('a.rp-jump')).map(a => [a.dataset.replay, "
                           "a.dataset.t])"):
        browser.click(f"a.rp-jump[data-replay='{link[0]}'][data-t='{link[1]}']")
        assert browser.js(f"window.rosgradeReplays[{link[0]!r}].t") == pytest.approx(float(link[1]))
